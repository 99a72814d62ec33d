// fieldcodec CLI — the decimal places at which a DPQ parameter's EU value reads back to the
// same raw value (dpq round_trip_places), with a fallback for scales beyond 10^18.
#pragma once

#include <fieldcodec/core/scaling.hpp>
#include <fieldcodec/dpq/parameter.hpp>

namespace fieldcodec::cli {
[[nodiscard]] inline unsigned dpq_round_trip_places(scaling::linear s) noexcept {
  return dpq::round_trip_places(s).value_or(18U);
}
} // namespace fieldcodec::cli
