// SPDX-License-Identifier: Apache-2.0
#include "option_flags.hpp"

#include <array>
#include <utility>

#include "vrreg/core/format.hpp"

namespace vrreg::cli {
namespace {

// Library option name -> command-line flag.
constexpr std::array<OptionWord, 12> kFlags{{
    {"config", "--config"},
    {"cube_edge", "--cube-mm"},
    {"export", "--export"},
    {"interpolation", "--interpolation"},
    {"joint_norm", "--joint-norm"},
    {"offset_tilt", "--offset-tilt-deg"},
    {"robot", "--robot"},
    {"robust", "--robust"},
    {"scale", "--scale"},
    {"seed", "--seed"},
    {"sigma_rep", "--sigma-rep-mm"},
    {"strategy", "--strategy"},
}};

}  // namespace

std::string with_flags(std::string message) {
  return with_option_words(std::move(message), kFlags);
}

}  // namespace vrreg::cli
