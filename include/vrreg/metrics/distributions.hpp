// SPDX-License-Identifier: Apache-2.0
#pragma once
// The chi-square and F distributions' upper tails and quantiles, for tests at a stated
// false-alarm rate (Eigen's regularised incomplete gamma and beta functions).

namespace vrreg {

/// P(chi2_k > x) for k > 0 degrees of freedom and x >= 0 (throws InputError otherwise).
double chi_square_survival(double x, double k);

/// The x with P(chi2_k > x) = `tail` (0 < tail < 1), to 1e-12 relative.
double chi_square_quantile_upper(double tail, double k);

/// P(F_{d1,d2} > x) for d1, d2 > 0 and x >= 0 (throws InputError otherwise).
double f_survival(double x, double d1, double d2);

/// The x with P(F_{d1,d2} > x) = `tail` (0 < tail < 1), to 1e-12 relative.
double f_quantile_upper(double tail, double d1, double d2);

/// The bound a sum of k squared standardised differences is tested against at false-alarm rate
/// `tail`: chi2_k's quantile when the variance is known (`variance_dof` 0), k F_{k,nu}'s when it
/// was estimated with nu = `variance_dof` degrees of freedom.
double squared_sum_bound(double tail, double k, double variance_dof);

/// Two independent sums of squares (k1 and k2 dof) each tested at rate `beta`, sharing one
/// variance estimate with nu = `variance_dof` dof (0: known variance): the beta for which P(either
/// alarms) = `tail`. Known variance: 1 - sqrt(1 - tail); estimated: the shared estimate makes the
/// tests dependent, and beta is found on P(both pass) = E_U[F_k1(t1 U/nu) F_k2(t2 U/nu)],
/// U ~ chi2_nu, by quadrature.
double split_rate(double tail, double k1, double k2, double variance_dof);

}  // namespace vrreg
