// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The readings a Jetson power rail can physically give, shared by the tegrastats and jtop importers. Beyond them a
// log is corrupt (a bit flip, a pasted 20-digit number), and averaging such a value would give a "mean power" of
// 1e17 W, so the importers refuse the file and name the line and the rail.
//  - Upper: 1 kW. The largest module, AGX Thor, is specified up to 130 W and a carrier's input rail stays well
//    under 300 W; 1 kW leaves room for any board without letting an absurd number through.
//  - Lower: -2 W. Rails do not give power back, but INA3221 channels read slightly negative near zero: AGX Thor's
//    tegrastats prints "VDD_GPU -392mW/-392mW" with the GPU power-gated. Such readings are kept as printed.
#include <string_view>

namespace bs {

inline constexpr double kMaxRailMilliwatts = 1.0e6;
inline constexpr double kMinRailMilliwatts = -2.0e3;
inline constexpr std::string_view kRailBoundText = "a rail reads between -2 W and 1 kW";

inline bool plausible_rail_milliwatts(double mw) noexcept {
  return mw >= kMinRailMilliwatts && mw <= kMaxRailMilliwatts;
}

}  // namespace bs
