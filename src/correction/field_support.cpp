// Checks the field models share (method_support.hpp).
#include <Eigen/QR>
#include <array>
#include <cmath>
#include <map>
#include <sstream>

#include "field_basis.hpp"
#include "method_support.hpp"
#include "point_index.hpp"

namespace vrreg::detail {
namespace {

/// Joint angles further apart than this at one nominal position are another arm configuration.
constexpr double kSameConfigurationRad = 1e-3;

}  // namespace

std::string configuration_clash(const CorrectorData& data, double tolerance_m) {
  if (!data.has_joints()) return {};
  std::map<std::array<long long, 3>, Eigen::Index> first_at;
  for (Eigen::Index j = 0; j < data.size(); ++j) {
    std::array<long long, 3> key{};
    for (int axis = 0; axis < 3; ++axis)
      key[static_cast<std::size_t>(axis)] =
          std::llround(data.fiducials_robot_m(axis, j) / tolerance_m);
    const auto [it, inserted] = first_at.emplace(key, j);
    if (inserted) continue;
    const Eigen::Index k = it->second;
    if ((data.joints_rad.col(j) - data.joints_rad.col(k)).cwiseAbs().maxCoeff() >
        kSameConfigurationRad) {
      std::ostringstream out;
      out << "fiducials " << k << " and " << j
          << " share a nominal robot position in different arm configurations (use joint, or "
             "one model per configuration)";
      return out.str();
    }
  }
  return {};
}

std::string polynomial_unavailable(const CorrectorData& data, int degree, const char* what) {
  const int terms = trend_terms(degree);
  if (data.size() < terms + 1) {
    return std::string(what) + ": " + std::to_string(data.size()) + " fiducials, a degree-" +
           std::to_string(degree) + " polynomial needs at least " + std::to_string(terms + 1);
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(
      trend_basis(data.fiducials_robot_m, degree, trend_frame(data.fiducials_robot_m)));
  if (qr.rank() < terms) {
    return std::string(what) + ": the " + std::to_string(data.size()) +
           " fiducial positions cannot determine a degree-" + std::to_string(degree) +
           " polynomial (coplanar or collinear?)";
  }
  return {};
}

std::string coincidence_unavailable(const CorrectorData& data, const char* what) {
  const double extent_m = trend_frame(data.fiducials_robot_m).scale_m;
  const PointIndex index(data.fiducials_robot_m);
  if (const auto pair = index.duplicate(1e-9 * extent_m)) {
    return std::string(what) + ": fiducials " + std::to_string(pair->first) + " and " +
           std::to_string(pair->second) + " share a position";
  }
  return {};
}

}  // namespace vrreg::detail
