// SPDX-License-Identifier: Apache-2.0
#pragma once
// One axis of a universal-kriging model conditioned on its data: posterior mean and latent sd
// at query points, the trend coefficients' uncertainty included (docs/field-models.md).
#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "field_basis.hpp"
#include "vrreg/core/types.hpp"
#include "vrreg/correction/kriging.hpp"

namespace vrreg::detail {

struct KrigingPosterior {
  Points3 positions_m;
  KrigingHyperparameters hyper;
  KrigingKernel kernel = KrigingKernel::matern52;
  int degree = 2;
  TrendFrame frame;
  Eigen::LLT<Eigen::MatrixXd> k_llt;      ///< K = C + nugget I = L L'
  Eigen::MatrixXd l_inv_f;                ///< L^-1 F
  Eigen::LLT<Eigen::MatrixXd> a_llt;      ///< A = F' K^-1 F
  Eigen::VectorXd beta;                   ///< GLS trend coefficients A^-1 F' K^-1 y
  Eigen::VectorXd alpha;                  ///< K^-1 (y - F beta)
};

/// A row of a column-major 3 x N matrix (stride 3) or a plain row vector.
using StridedRow = Eigen::Ref<Eigen::RowVectorXd, 0, Eigen::InnerStride<>>;

/// Conditions on (positions_m, values); throws InputError when K or A is not positive definite
/// (e.g. the positions cannot determine the trend).
[[nodiscard]] KrigingPosterior condition_kriging(const ConstPoints3Ref& positions_m,
                                                 const Eigen::VectorXd& values,
                                                 const KrigingHyperparameters& hyper,
                                                 KrigingKernel kernel, int degree,
                                                 const TrendFrame& frame);

/// Universal-kriging mean f' beta + k' alpha and latent variance
/// s^2 - k' K^-1 k + u' A^-1 u, u = f - F' K^-1 k, at the columns of query_m.
void predict_kriging(const KrigingPosterior& posterior, const ConstPoints3Ref& query_m,
                     StridedRow mean, StridedRow sd);

}  // namespace vrreg::detail
