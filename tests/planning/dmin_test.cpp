// SPDX-License-Identifier: Apache-2.0
// The d_min > 2.5 sigma_noise criterion (paper Eq. 9): an error naming the values unless forced.
#include <string>

#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/robots.hpp"
#include "vrreg/planning/dmin_criterion.hpp"
#include "vrreg/planning/plan.hpp"
#include "vrreg_test.hpp"

namespace vrreg::planning {
namespace {

TEST(DminCheck, PassesAboveTwoAndAHalfSigmaNoise) {
  const DminCheck c = check_dmin(0.3e-3, 0.114e-3, false);
  EXPECT_TRUE(c.ok);
  EXPECT_FALSE(c.forced);
  EXPECT_NEAR(c.threshold_m, 0.285e-3, 1e-15);
  EXPECT_NEAR(min_spacing_for_noise_m(0.114e-3) * std::sqrt(3.0) / 2.0, 0.285e-3, 1e-15);
}

TEST(DminCheck, FailsWithTheValuesInTheMessage) {
  try {
    (void)check_dmin(0.25e-3, 0.114e-3, false);
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("d_min = 0.250 mm"), std::string::npos) << what;
    EXPECT_NE(what.find("2.5 * sigma_noise = 0.285 mm"), std::string::npos) << what;
    EXPECT_NE(what.find("0.329 mm"), std::string::npos) << what;  // smallest spacing that passes
  }
  // Equality fails too: the criterion is strict.
  EXPECT_THROW(check_dmin(0.285e-3, 0.114e-3, false), InputError);
}

TEST(DminCheck, ForceGoesOnAndSaysSo) {
  const DminCheck c = check_dmin(0.25e-3, 0.114e-3, true);
  EXPECT_FALSE(c.ok);
  EXPECT_TRUE(c.forced);
  EXPECT_THROW(check_dmin(0.25e-3, 0.0, true), InputError);
  EXPECT_THROW(check_dmin(-1.0, 0.1e-3, true), InputError);
}

TEST(DminCheck, PlanRefusesATooFineGridUnlessForced) {
  const kinematics::SerialChain chain = kinematics::ur5();
  const std::vector<PartPoint> parts{{"P", Eigen::Vector3d(0.45, -0.1, 0.25)}};
  PlanOptions options;
  options.halfwidth_m = 0.0005;
  options.spacing_m = 0.0003;  // d_min = 0.26 mm <= 0.285 mm
  EXPECT_THROW(make_plan(chain, parts, options), InputError);
  options.force = true;
  const PlanResult r = make_plan(chain, parts, options);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_TRUE(r.dmin.forced);
  EXPECT_FALSE(r.dmin.ok);
  // A larger sigma_noise moves the limit: 5 mm spacing fails for sigma_noise = 2 mm.
  options.force = false;
  options.halfwidth_m = 0.0075;
  options.spacing_m = 0.005;
  options.sigma_noise_m = 2e-3;
  EXPECT_THROW(make_plan(chain, parts, options), InputError);
}

}  // namespace
}  // namespace vrreg::planning
