#pragma once
// The two sides of a car, as every formulation indexes them: 0 is the left rail, at
// +y in the car's lateral axis, and 1 the right, at −y. Channel names end in the
// side's letter (ChannelLayout.h).

namespace rockroll {

inline constexpr int kLeft = 0;
inline constexpr int kRight = 1;
/// Sign of the side's lateral coordinate: y = kSideSign[side]·(half gauge, half spacing, ...).
inline constexpr double kSideSign[2] = {+1.0, -1.0};
inline constexpr const char* kSideName[2] = {"L", "R"};

}  // namespace rockroll
