// SPDX-License-Identifier: Apache-2.0
#pragma once
// Beyond the paper (docs/field-models.md): correction methods compared by K-fold cross-validation
// on the fiducials, and `--interpolation auto`'s choice. Folds are dealt by cluster, not by
// fiducial: fiducials much closer together than the layout's spacing (a dense cluster beside a
// sparse grid) go to one fold together, so that none of them is predicted from its twins.
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "vrreg/correction/correction_method.hpp"
#include "vrreg/correction/corrector_data.hpp"
#include "vrreg/correction/interpolation.hpp"

namespace vrreg {

/// Above this many fiducials (a scanner's or laser tracker's cell) cross-validation holds out one
/// seeded sample of about kLargeCellHeldOut fiducials, predicted by one model fitted on all the
/// rest, instead of K folds (docs/field-models.md, "Large cells").
inline constexpr Eigen::Index kLargeCellFiducials = 20000;
inline constexpr Eigen::Index kLargeCellHeldOut = 2000;

/// One method's K-fold cross-validation on the fiducials: each fold's corrections predicted by
/// the model fitted on the other folds, at the fold's registered positions.
struct CrossValidationRow {
  InterpolationMethod method = InterpolationMethod::kTrilinear;
  bool applicable = false;  ///< false: `note` says why (e.g. no joints, not a lattice)
  std::string note{};
  double rms_m = 0.0;  ///< RMS over the predicted fiducials of |predicted - measured| (3D) [m]
  Eigen::Vector3d rms_axis_m = Eigen::Vector3d::Zero();  ///< the same per sensor axis [m]
  Eigen::Index n_predicted = 0;  ///< fiducials the held-out models could predict
  /// Held-out fiducials not predicted because they registered outside the box of the fold's
  /// training fiducials: the method's support, not a failure of its fit (its own RMS leaves
  /// them out; auto's ranking counts them at their uncorrected error).
  Eigen::Index n_outside_training = 0;
  /// RMS (3D) over the fiducials any compared method predicted, this method's misses among them
  /// at their uncorrected error: what `auto` ranks by [m].
  double rms_ranked_m = 0.0;
  /// |predicted - measured|^2 per fiducial [m^2]; NaN where not predicted.
  Eigen::VectorXd squared_error_m2{};
  double seconds = 0.0;  ///< fit and predict over all folds (wall time)
};

/// The table `--interpolation auto` prints, and its choice: the lowest RMS over the fiducials
/// any compared method predicted, each method's misses at their uncorrected error (lattice and
/// Delaunay methods cannot predict at the layout's edge: comparing each over its own subset
/// would favour them, comparing on the subset all predicted favours models good in the interior).
struct CrossValidation {
  /// K folds, or 1: a large cell's one held-out sample (kLargeCellFiducials).
  int folds = 5;
  Eigen::Index n_ranked = 0;  ///< fiducials in the ranking (any method predicted them)
  std::uint64_t seed = 1;     ///< of the shuffle that deals the fold units to folds
  /// Fold units: fiducials dealt to folds together (clusters; == the fiducial count when every
  /// fiducial stands alone, as on a lattice).
  Eigen::Index n_units = 0;
  std::vector<CrossValidationRow> rows{};
  InterpolationMethod chosen = InterpolationMethod::kTrilinear;
};

/// The fold units of fiducials at `positions_m` [m]: unit index per fiducial (0..U-1, in order of
/// first appearance). Fiducials closer than a third of the layout's spacing (the cube root of
/// the bounding box's volume per fiducial) are linked, and a unit is a connected group; on a
/// lattice or a spread-out layout every fiducial is its own unit.
std::vector<Eigen::Index> fold_units(const ConstPoints3Ref& positions_m);

/// Fold (0..folds-1) of each fiducial: the units in a seeded shuffle dealt round-robin, so folds
/// differ by at most one unit and do not follow the file's (spatial) order.
std::vector<int> assign_folds(const std::vector<Eigen::Index>& unit_of, int folds,
                              std::uint64_t seed);

/// One method's row: checked (CorrectionMethod::unavailable), fitted on all fiducials (into
/// `full` when given), then for every fold refitted on the others (FittedMethod::refit) and
/// predicted on it. A fold whose fit does not apply leaves its fiducials unpredicted; an
/// exception inside a fit propagates. The RMS weighs each fold unit (`unit_of`, fold_units) as
/// one fiducial. The time covers it all.
CrossValidationRow cross_validate(InterpolationMethod method, const CorrectorData& data,
                                  const MethodSettings& settings, const std::vector<int>& fold_of,
                                  const std::vector<Eigen::Index>& unit_of, int folds,
                                  FitOutcome* full = nullptr);

/// The methods `auto` chooses among, in the order of the table.
std::vector<InterpolationMethod> auto_candidates();

/// Every candidate's row and the choice: the lowest RMS among applicable methods on the fiducials
/// they all predicted. Throws InputError when no method qualifies. `chosen` (when given) receives
/// the chosen method fitted on all fiducials.
CrossValidation choose_by_cross_validation(const CorrectorData& data,
                                           const MethodSettings& settings, int folds = 5,
                                           std::uint64_t seed = 1, FitOutcome* chosen = nullptr);

}  // namespace vrreg
