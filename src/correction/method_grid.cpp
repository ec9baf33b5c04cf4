// SPDX-License-Identifier: Apache-2.0
// Trilinear RRBC weights in a complete regular grid of fiducials (Eq. 7) as a correction method.
// The grid found in the fiducials is saved: finding it again can take long on a large layout.
#include <array>
#include <cmath>

#include "grid_stencil.hpp"
#include "method_support.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/correction/grid.hpp"

namespace vrreg::detail {
namespace {

class GridMethod final : public FittedMethod {
 public:
  GridMethod(GridLayout grid, const CorrectorData& data, const MethodSettings& settings)
      : grid_(std::move(grid)),
        corrections_sensor_m_(data.corrections_sensor_m),
        slack_(grid_slack(grid_, settings.match_tolerance_m)) {}

  [[nodiscard]] InterpolationMethod method() const override { return InterpolationMethod::kGrid; }
  [[nodiscard]] std::string describe() const override { return grid_.describe(); }

  void predict(const MethodQuery& query, Eigen::Index begin, Eigen::Index end,
               MethodPredictions& out) const override {
    for (Eigen::Index i = begin; i < end; ++i) {
      Stencil& stencil = out.stencils[static_cast<std::size_t>(i)];  // written in place
      grid_stencil_into(grid_, query.registered_robot_m.col(i), slack_, stencil);
      if (stencil.status == StencilStatus::kOk) {
        out.corrections_sensor_m.col(i) = interpolate_correction(stencil, corrections_sensor_m_);
      } else {
        out.corrections_sensor_m.col(i).setZero();
      }
    }
  }

  [[nodiscard]] MethodState save() const override {
    MethodState s("grid");
    s.put("origin_m", Eigen::MatrixXd(grid_.origin_m));
    s.put("spacing_m", Eigen::MatrixXd(grid_.spacing_m));
    s.put("nodes", Eigen::MatrixXd(Eigen::Vector3d(grid_.nodes[0], grid_.nodes[1], grid_.nodes[2])));
    s.put("stride", grid_.stride);
    s.put("n_lattice_fiducials", static_cast<double>(grid_.n_fiducials));
    Eigen::MatrixXd node_fiducial(static_cast<Eigen::Index>(grid_.fiducial.size()), 1);
    for (std::size_t n = 0; n < grid_.fiducial.size(); ++n)
      node_fiducial(static_cast<Eigen::Index>(n), 0) = static_cast<double>(grid_.fiducial[n]);
    s.put("node_fiducial", std::move(node_fiducial));
    return s;
  }

 private:
  GridLayout grid_;
  Points3 corrections_sensor_m_;
  std::array<double, 3> slack_;
};

FitOutcome fit_grid(const CorrectorData& data, const MethodSettings& settings) {
  GridDetection detection = detect_grid(data.fiducials_robot_m, settings.match_tolerance_m);
  if (!detection.grid) return not_applicable(detection.reason);
  return fitted<GridMethod>(std::move(*detection.grid), data, settings);
}

// The saved grid, checked against the fiducials: every node must hold the fiducial it names.
std::unique_ptr<const FittedMethod> restore_grid(const MethodState& state,
                                                 const CorrectorData& data,
                                                 const MethodSettings& settings) {
  GridLayout grid;
  grid.origin_m = state.array("origin_m", 3, 1);
  grid.spacing_m = state.array("spacing_m", 3, 1);
  std::int64_t total = 1;
  for (std::size_t a = 0; a < 3; ++a) {
    const Eigen::MatrixXd& nodes = state.array("nodes", 3, 1);
    const double v = nodes(static_cast<Eigen::Index>(a), 0);
    VRREG_THROW_UNLESS(v == std::floor(v) && v >= 2 && v <= 1e6,
                       "the saved grid corrector's nodes are not whole numbers >= 2");
    grid.nodes[a] = static_cast<int>(v);
    total *= grid.nodes[a];
  }
  VRREG_THROW_UNLESS((grid.spacing_m.array() > 0.0).all(),
                     "the saved grid corrector's spacing is not positive");
  grid.stride = static_cast<int>(state.integer("stride", 1, 1000000));
  grid.n_fiducials = static_cast<Eigen::Index>(state.integer("n_lattice_fiducials", 1, data.size()));
  const Eigen::MatrixXd& node_fiducial = state.array("node_fiducial", total, 1);
  const double tolerance_m = settings.match_tolerance_m;
  for (Eigen::Index n = 0; n < total; ++n) {
    const double f = node_fiducial(n, 0);
    VRREG_THROW_UNLESS(f == std::floor(f) && f >= 0 && f < static_cast<double>(data.size()),
                       "the saved grid corrector's node " << n << " names fiducial " << f << " of "
                                                          << data.size());
    const auto j = static_cast<Eigen::Index>(f);
    const Eigen::Index i = n % grid.nodes[0];
    const Eigen::Index k = n / (static_cast<Eigen::Index>(grid.nodes[0]) * grid.nodes[1]);
    const Eigen::Index jj = (n / grid.nodes[0]) % grid.nodes[1];
    const Eigen::Vector3d node_m =
        grid.origin_m + Eigen::Vector3d(static_cast<double>(i), static_cast<double>(jj),
                                        static_cast<double>(k))
                            .cwiseProduct(grid.spacing_m);
    VRREG_THROW_UNLESS((data.fiducials_robot_m.col(j) - node_m).cwiseAbs().maxCoeff() <=
                           tolerance_m * (1.0 + 1e-9) + 1e-12 * node_m.norm(),
                       "the saved grid corrector's node " << n << " is not at fiducial " << j);
    grid.fiducial.push_back(j);
  }
  return std::make_unique<const GridMethod>(std::move(grid), data, settings);
}

}  // namespace

CorrectionMethod grid_method() {
  return {InterpolationMethod::kGrid, false, nullptr, fit_grid, restore_grid};
}

}  // namespace vrreg::detail
