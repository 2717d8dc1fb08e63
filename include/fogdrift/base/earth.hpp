// Earth constants shared by the simulator and the north-finding solver.
#pragma once

namespace fogdrift {

/// Earth's sidereal rotation rate, °/h (7.292115e-5 rad/s, IERS conventions).
inline constexpr double kEarthRateDph = 15.041067;

}  // namespace fogdrift
