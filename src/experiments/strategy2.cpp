#include "vrreg/experiments/strategy2.hpp"

#include "vrreg/core/check.hpp"

namespace vrreg::experiments {

std::vector<std::vector<int>> strategy2_order(const std::vector<Eigen::MatrixXd>& configurations,
                                              kinematics::JointNorm norm) {
  std::vector<std::vector<int>> order;
  order.reserve(configurations.size());
  Eigen::VectorXd reference;
  for (std::size_t p = 0; p < configurations.size(); ++p) {
    const Eigen::MatrixXd& q = configurations[p];
    VRREG_THROW_UNLESS(q.cols() > 0, "Strategy 2: point " << p << " has no configuration");
    int nearest = 0;
    if (p > 0) {
      VRREG_THROW_UNLESS(q.rows() == reference.size(), "Strategy 2: point "
                                                           << p << " has " << q.rows()
                                                           << " joints, not " << reference.size());
      nearest = *kinematics::nearest_configuration(q, reference, norm);
    }
    reference = q.col(nearest);
    std::vector<int> sorted = kinematics::order_by_distance(q, reference, norm);
    // The reference is at distance 0 and comes first unless another configuration coincides.
    for (std::size_t m = 0; m < sorted.size(); ++m) {
      if (sorted[m] == nearest) {
        sorted.erase(sorted.begin() + static_cast<std::ptrdiff_t>(m));
        break;
      }
    }
    sorted.insert(sorted.begin(), nearest);
    order.push_back(std::move(sorted));
  }
  return order;
}

double switched_fraction(const std::vector<std::vector<int>>& order) {
  if (order.empty()) return 0.0;
  int switched = 0;
  for (const std::vector<int>& o : order) {
    for (std::size_t m = 0; m < o.size(); ++m) {
      if (o[m] != static_cast<int>(m)) {
        ++switched;
        break;
      }
    }
  }
  return static_cast<double>(switched) / static_cast<double>(order.size());
}

}  // namespace vrreg::experiments
