// SPDX-License-Identifier: Apache-2.0
// The commands against an independent implementation of the paper's equations, written here from
// scratch (own CSV parsing, Horn's quaternion registration, brute-force sigma_L, hand-made
// octuplet and trilinear weights): register/evaluate/correct must agree to 1e-6 mm.
#include <cmath>
#include <map>
#include <sstream>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace vrreg::testing {
namespace {

struct Loc {
  std::string point;
  bool target = false;
  Eigen::Vector3d robot_mm = Eigen::Vector3d::Zero();
  Eigen::Vector3d sensor_sum_mm = Eigen::Vector3d::Zero();
  int k = 0;
  Eigen::Vector3d sensor_mm() const { return sensor_sum_mm / k; }
};

// The example file: header with point,role,robot_*_mm,sensor_*_mm,repeat.
std::vector<Loc> parse(const std::string& path) {
  std::istringstream in(read_text(path));
  std::string line;
  std::vector<Loc> locs;
  std::map<std::string, std::size_t> index;
  bool header = true;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (header) {
      header = false;
      continue;
    }
    std::vector<std::string> f;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) f.push_back(cell);
    auto [it, fresh] = index.try_emplace(f[0], locs.size());
    if (fresh) {
      locs.push_back({f[0], f[1] == "target",
                      Eigen::Vector3d(std::stod(f[2]), std::stod(f[3]), std::stod(f[4]))});
    }
    Loc& l = locs[it->second];
    l.sensor_sum_mm += Eigen::Vector3d(std::stod(f[5]), std::stod(f[6]), std::stod(f[7]));
    ++l.k;
  }
  return locs;
}

// Horn (1987): rotation from the dominant eigenvector of the 4x4 quaternion matrix.
void horn(const std::vector<Eigen::Vector3d>& x, const std::vector<Eigen::Vector3d>& y,
          Eigen::Matrix3d& r, Eigen::Vector3d& t) {
  Eigen::Vector3d mx = Eigen::Vector3d::Zero(), my = Eigen::Vector3d::Zero();
  for (std::size_t j = 0; j < x.size(); ++j) mx += x[j], my += y[j];
  mx /= static_cast<double>(x.size());
  my /= static_cast<double>(x.size());
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
  for (std::size_t j = 0; j < x.size(); ++j) m += (x[j] - mx) * (y[j] - my).transpose();
  Eigen::Matrix4d n;
  n << m(0, 0) + m(1, 1) + m(2, 2), m(1, 2) - m(2, 1), m(2, 0) - m(0, 2), m(0, 1) - m(1, 0),
      m(1, 2) - m(2, 1), m(0, 0) - m(1, 1) - m(2, 2), m(0, 1) + m(1, 0), m(2, 0) + m(0, 2),
      m(2, 0) - m(0, 2), m(0, 1) + m(1, 0), -m(0, 0) + m(1, 1) - m(2, 2), m(1, 2) + m(2, 1),
      m(0, 1) - m(1, 0), m(2, 0) + m(0, 2), m(1, 2) + m(2, 1), -m(0, 0) - m(1, 1) + m(2, 2);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eig(n);
  const Eigen::Vector4d q = eig.eigenvectors().col(3);
  r = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).toRotationMatrix();
  t = my - r * mx;
}

nlohmann::json run_json(const std::string& args) {
  const CliResult r = run_vrreg(args + " --json");
  EXPECT_EQ(r.status, 0) << r.err;
  return nlohmann::json::parse(r.out);
}

TEST(IndependentReference, RegisterEvaluateCorrectMatchThePaperEquations) {
  const std::string data = std::string(VRREG_SOURCE_DIR) + "/examples/data/example-cell.csv";
  const auto dir = fresh_dir("independent");
  const std::string model = (dir / "m.json").string();

  // --- independent computation (mm throughout) ---
  const std::vector<Loc> locs = parse(data);
  std::vector<Eigen::Vector3d> fx, fy;
  std::map<std::tuple<long, long, long>, Eigen::Vector3d> eps_at;  // by nominal robot position
  for (const Loc& l : locs) {
    if (!l.target) fx.push_back(l.sensor_mm()), fy.push_back(l.robot_mm);
  }
  Eigen::Matrix3d r;
  Eigen::Vector3d t;
  horn(fx, fy, r, t);
  double fre_sq = 0.0;
  for (std::size_t j = 0; j < fx.size(); ++j) fre_sq += (r * fx[j] + t - fy[j]).squaredNorm();
  const double fre = std::sqrt(fre_sq / static_cast<double>(fx.size()));
  long double sum = 0, sum_sq = 0;
  long count = 0;
  for (std::size_t i = 0; i < fx.size(); ++i) {
    for (std::size_t j = i + 1; j < fx.size(); ++j) {
      const long double l = (fx[i] - fx[j]).norm() - (fy[i] - fy[j]).norm();
      sum += l, sum_sq += l * l, ++count;
    }
  }
  const double sigma_l =
      static_cast<double>(std::sqrt((sum_sq - sum * sum / count) / (count - 1)));
  auto key = [](const Eigen::Vector3d& p) {
    return std::make_tuple(std::lround(p[0] * 1000), std::lround(p[1] * 1000),
                           std::lround(p[2] * 1000));
  };
  for (std::size_t j = 0; j < fx.size(); ++j) {
    eps_at[key(fy[j])] = r.transpose() * fy[j] - r.transpose() * t - fx[j];  // Eq. 6
  }
  // Octuplet, 50 mm cube (Eq. 7 with w = 1/8) and trilinear in the 50 mm cell (grid).
  std::vector<double> unc, cor_oct;
  std::map<std::string, Eigen::Vector3d> corrected_grid;
  for (const Loc& l : locs) {
    if (!l.target) continue;
    Eigen::Vector3d eps_oct = Eigen::Vector3d::Zero();
    Eigen::Vector3d eps_tri = Eigen::Vector3d::Zero();
    const Eigen::Vector3d lo = l.robot_mm - Eigen::Vector3d::Constant(25.0);
    const Eigen::Vector3d p = r * l.sensor_mm() + t;  // registered position picks the weights
    const Eigen::Vector3d u = (p - lo) / 50.0;
    for (int c = 0; c < 8; ++c) {
      const Eigen::Vector3d bits(c & 1, (c >> 1) & 1, (c >> 2) & 1);
      const Eigen::Vector3d e = eps_at.at(key(lo + 50.0 * bits));
      eps_oct += e / 8.0;
      double w = 1.0;
      for (int a = 0; a < 3; ++a) w *= bits[a] > 0 ? u[a] : 1.0 - u[a];
      eps_tri += w * e;
    }
    unc.push_back((r * l.sensor_mm() + t - l.robot_mm).norm());
    cor_oct.push_back((r * (l.sensor_mm() + eps_oct) + t - l.robot_mm).norm());  // Eq. 8, 3
    corrected_grid[l.point] = r * (l.sensor_mm() + eps_tri) + t;
  }
  auto rms = [](const std::vector<double>& v) {
    double s = 0;
    for (double e : v) s += e * e;
    return std::sqrt(s / static_cast<double>(v.size()));
  };
  int n_bad = 0;
  for (std::size_t n = 0; n < unc.size(); ++n) n_bad += cor_oct[n] > unc[n] ? 1 : 0;

  // --- the commands ---
  const nlohmann::json reg = run_json("register --fiducials '" + data + "' -o '" + model + "'");
  EXPECT_EQ(reg["n_fiducials"], fx.size());
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(reg["translation_mm"][i].get<double>(), t[i], 1e-6);
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(reg["rotation"][i][j].get<double>(), r(i, j), 1e-9);
  }
  EXPECT_NEAR(reg["fre_mm"].get<double>(), fre, 1e-6);
  EXPECT_NEAR(reg["sigma_l_mm"].get<double>(), sigma_l, 1e-6);

  const nlohmann::json ev = run_json("evaluate --model '" + model + "' --targets '" + data +
                                     "' --interpolation octuplet --cube-mm 50");
  EXPECT_EQ(ev["n_targets"], unc.size());
  EXPECT_NEAR(ev["unc_rms_t_mm"].get<double>(), rms(unc), 1e-6);
  EXPECT_NEAR(ev["cor_rms_t_mm"].get<double>(), rms(cor_oct), 1e-6);
  EXPECT_NEAR(ev["gamma_percent"].get<double>(), 100 * (rms(unc) - rms(cor_oct)) / rms(unc), 1e-4);
  EXPECT_EQ(ev["n_bad"], n_bad);

  const std::string out = (dir / "corrected.csv").string();
  const nlohmann::json co = run_json("correct --model '" + model + "' --points '" + data +
                                     "' --interpolation grid -o '" + out + "'");
  EXPECT_EQ(co["interpolation"], "grid");
  std::istringstream rows(read_text(out));
  std::string line;
  int checked = 0;
  while (std::getline(rows, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("point,", 0) == 0) continue;
    std::vector<std::string> f;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) f.push_back(cell);
    ASSERT_GE(f.size(), 6u);
    EXPECT_EQ(f[2], "ok");
    const Eigen::Vector3d got(std::stod(f[3]), std::stod(f[4]), std::stod(f[5]));
    EXPECT_LT((got - corrected_grid.at(f[0])).norm(), 1e-6) << f[0];
    ++checked;
  }
  EXPECT_EQ(checked, static_cast<int>(unc.size()));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace vrreg::testing
