#include "vrreg/correction/correct_targets.hpp"

#if defined(__linux__)
#include <sys/mman.h>
#endif
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>

#include "grid_stencil.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/correction/grid.hpp"
#include "vrreg/correction/octuplet.hpp"
#include "vrreg/correction/scattered.hpp"

namespace vrreg {
namespace {

constexpr Eigen::Index kParallelGrain = 4096;  // targets per task; fewer run serially

// The result of 10^6 targets is ~230 MB of fresh memory: with 4 KiB pages, faulting it in cost
// more than the interpolation. Asks Linux for transparent huge pages on a buffer not yet touched
// (a hint: nothing changes where it is not honoured).
void advise_huge_pages(const void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20U;
  if (bytes < 4 * kHugePage) return;
  const auto address = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t begin = (address + kHugePage - 1) & ~(kHugePage - 1);
  const std::uintptr_t end = (address + bytes) & ~(kHugePage - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)data;
  (void)bytes;
#endif
}

// Faults a fresh buffer's pages in from both threads (the kernel zeroes each page on its first
// touch), so that a serial pass over it, std::vector's value-initialisation, only writes memory.
void fault_in_parallel(void* data, std::size_t bytes) {
  constexpr std::size_t kPage = 4096;
  constexpr std::size_t kPagesPerTask = 256;
  if (bytes < 4 * kPagesPerTask * kPage) return;
  auto* const bytes_begin = static_cast<unsigned char*>(data);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, bytes, kPagesPerTask * kPage),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t b = r.begin(); b < r.end(); b += kPage) bytes_begin[b] = 0;
                    });
}

// Sizes a 3 x n result without touching it (the parallel loop writes every entry first).
void allocate(Points3& points, Eigen::Index n) {
  points.resize(3, n);
  advise_huge_pages(points.data(), static_cast<std::size_t>(3 * n) * sizeof(double));
}

void check_inputs(const CorrectionField& field, const ConstPoints3Ref& targets_sensor_m,
                  const ConstPoints3Ref& targets_robot_nominal_m,
                  const InterpolationSettings& settings) {
  const Eigen::Index n_fiducials = field.fiducials_robot_m.cols();
  VRREG_THROW_UNLESS(n_fiducials > 0, "the model has no fiducials to correct with");
  VRREG_THROW_UNLESS(field.corrections_sensor_m.cols() == n_fiducials,
                     "the model has " << field.corrections_sensor_m.cols()
                                      << " fiducial corrections for " << n_fiducials
                                      << " fiducials");
  VRREG_THROW_UNLESS(field.corrections_sensor_m.allFinite(),
                     "the model's fiducial corrections are not all finite");
  const SimilarityTransform& T = field.T_robot_sensor;
  VRREG_THROW_UNLESS(T.rotation.allFinite() && T.translation_m.allFinite() &&
                         std::isfinite(T.scale) && T.scale > 0.0,
                     "the model's transform is not finite (scale " << T.scale << ")");
  for (Eigen::Index j = 0; j < n_fiducials; ++j) {
    VRREG_THROW_UNLESS(field.fiducials_robot_m.col(j).allFinite(),
                       "fiducial " << j << " has no finite nominal robot position");
  }
  VRREG_THROW_UNLESS(field.fiducials_sequence.empty() ||
                         field.fiducials_sequence.size() == static_cast<std::size_t>(n_fiducials),
                     "got " << field.fiducials_sequence.size() << " sequence numbers for "
                            << n_fiducials << " fiducials");
  VRREG_THROW_UNLESS(targets_sensor_m.allFinite(),
                     "the targets' sensor coordinates are not all finite");
  VRREG_THROW_UNLESS(targets_robot_nominal_m.cols() == 0 ||
                         targets_robot_nominal_m.cols() == targets_sensor_m.cols(),
                     "got " << targets_robot_nominal_m.cols() << " nominal robot positions for "
                            << targets_sensor_m.cols() << " targets");
  VRREG_THROW_UNLESS(targets_robot_nominal_m.allFinite(),
                     "the targets' nominal robot coordinates are not all finite");
  VRREG_THROW_UNLESS(std::isfinite(settings.match_tolerance_m) && settings.match_tolerance_m > 0.0,
                     "the match tolerance must be > 0, got " << settings.match_tolerance_m << " m");
}

}  // namespace

TargetCorrection correct_targets(const CorrectionField& field,
                                 const ConstPoints3Ref& targets_sensor_m,
                                 const ConstPoints3Ref& targets_robot_nominal_m,
                                 const InterpolationSettings& settings,
                                 const std::vector<std::size_t>& targets_sequence) {
  check_inputs(field, targets_sensor_m, targets_robot_nominal_m, settings);
  const Eigen::Index n = targets_sensor_m.cols();
  const double tolerance_m = settings.match_tolerance_m;
  const Points3& fiducials_robot_m = field.fiducials_robot_m;

  // Build the interpolator once; `stencil_of(i)` then only reads it (safe in parallel).
  TargetCorrection out;
  std::optional<GridLayout> grid;
  std::optional<OctupletStencils> octuplet;
  std::optional<ScatteredStencils> scattered;
  InterpolationMethod method = settings.method;
  if (method == InterpolationMethod::kLinear || method == InterpolationMethod::kGrid) {
    GridDetection detection = detect_grid(fiducials_robot_m, tolerance_m);
    VRREG_THROW_UNLESS(
        detection.grid || method == InterpolationMethod::kLinear,
        "grid interpolation needs fiducials on a complete regular grid: " << detection.reason);
    if (detection.grid) {
      grid = std::move(detection.grid);
      method = InterpolationMethod::kGrid;
      out.layout = grid->describe();
    } else {
      method = InterpolationMethod::kScattered;
    }
  }
  if (method == InterpolationMethod::kOctuplet) {
    VRREG_THROW_UNLESS(targets_robot_nominal_m.cols() == n,
                       "octuplet interpolation needs the targets' nominal robot positions");
    VRREG_THROW_UNLESS(targets_sequence.empty() ||
                           targets_sequence.size() == static_cast<std::size_t>(n),
                       "got " << targets_sequence.size() << " sequence numbers for " << n
                              << " targets");
    std::vector<std::size_t> fiducial_sequence;
    const bool sequenced =
        !targets_sequence.empty() && !field.fiducials_sequence.empty() &&
        std::all_of(field.fiducials_sequence.begin(), field.fiducials_sequence.end(),
                    [](std::size_t line) { return line > 0; });
    if (sequenced) fiducial_sequence = field.fiducials_sequence;
    octuplet.emplace(fiducials_robot_m, settings.cube_edge_m, tolerance_m,
                     std::move(fiducial_sequence));
    out.layout = octuplet->describe();
  } else if (method == InterpolationMethod::kScattered) {
    scattered.emplace(fiducials_robot_m, tolerance_m);
    out.layout = scattered->describe();
  }
  out.method_used = method;

  const SimilarityTransform& T_robot_sensor = field.T_robot_sensor;
  out.stencils.reserve(static_cast<std::size_t>(n));
  advise_huge_pages(out.stencils.data(), static_cast<std::size_t>(n) * sizeof(Stencil));
  fault_in_parallel(out.stencils.data(), static_cast<std::size_t>(n) * sizeof(Stencil));
  out.stencils.resize(static_cast<std::size_t>(n));
  allocate(out.corrections_sensor_m, n);
  allocate(out.corrected_sensor_m, n);
  allocate(out.corrected_robot_m, n);
  allocate(out.uncorrected_robot_m, n);
  const std::array<double, 3> grid_slack =
      grid ? detail::grid_slack(*grid, tolerance_m) : std::array<double, 3>{};
  std::atomic<int> n_flagged{0};
  const auto correct_range = [&](Eigen::Index begin, Eigen::Index end) {
    int flagged = 0;
    for (Eigen::Index i = begin; i < end; ++i) {
      const Eigen::Vector3d target_sensor_m = targets_sensor_m.col(i);
      const Eigen::Vector3d registered_robot_m = T_robot_sensor.apply(target_sensor_m);
      Stencil& stencil = out.stencils[static_cast<std::size_t>(i)];  // written in place
      if (grid) {
        detail::grid_stencil_into(*grid, registered_robot_m, grid_slack, stencil);
      } else if (octuplet) {
        stencil = octuplet->stencil(
            targets_robot_nominal_m.col(i),
            targets_sequence.empty() ? 0 : targets_sequence[static_cast<std::size_t>(i)]);
      } else {
        stencil = scattered->stencil(registered_robot_m);
      }
      out.uncorrected_robot_m.col(i) = registered_robot_m;
      if (stencil.status == StencilStatus::kOk) {
        const Eigen::Vector3d correction_m =  // Eq. 7
            interpolate_correction(stencil, field.corrections_sensor_m);
        out.corrections_sensor_m.col(i) = correction_m;
        out.corrected_sensor_m.col(i) = target_sensor_m + correction_m;  // Eq. 8
        out.corrected_robot_m.col(i) =
            T_robot_sensor.apply(Eigen::Vector3d(target_sensor_m + correction_m));
      } else {
        ++flagged;
        out.corrections_sensor_m.col(i).setZero();
        out.corrected_sensor_m.col(i) = target_sensor_m;
        out.corrected_robot_m.col(i) = registered_robot_m;
      }
    }
    n_flagged.fetch_add(flagged, std::memory_order_relaxed);
  };
  if (n < 2 * kParallelGrain) {
    correct_range(0, n);
  } else {
    tbb::parallel_for(tbb::blocked_range<Eigen::Index>(0, n, kParallelGrain),
                      [&](const tbb::blocked_range<Eigen::Index>& range) {
                        correct_range(range.begin(), range.end());
                      });
  }
  out.n_flagged = n_flagged.load();
  return out;
}

}  // namespace vrreg
