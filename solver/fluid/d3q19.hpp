#pragma once
// The D3Q19 velocity set: discrete velocities c_q, weights w_q and opposite
// directions, in lattice units (dx = dt = 1, speed of sound c_s^2 = 1/3).
#include <array>

namespace rbcal::solver::d3q19 {

inline constexpr int Q = 19;
inline constexpr double cs2 = 1.0 / 3.0;

// Order: rest, the six face neighbours, then the twelve edge neighbours.
// Opposite directions sit next to each other (q odd, q+1), so pair loops are simple.
inline constexpr std::array<std::array<int, 3>, Q> c = {{
    {0, 0, 0},
    {1, 0, 0},  {-1, 0, 0},  {0, 1, 0},  {0, -1, 0},  {0, 0, 1},  {0, 0, -1},
    {1, 1, 0},  {-1, -1, 0}, {1, -1, 0}, {-1, 1, 0},
    {1, 0, 1},  {-1, 0, -1}, {1, 0, -1}, {-1, 0, 1},
    {0, 1, 1},  {0, -1, -1}, {0, 1, -1}, {0, -1, 1},
}};

inline constexpr std::array<double, Q> w = {
    1.0 / 3.0,
    1.0 / 18.0, 1.0 / 18.0, 1.0 / 18.0, 1.0 / 18.0, 1.0 / 18.0, 1.0 / 18.0,
    1.0 / 36.0, 1.0 / 36.0, 1.0 / 36.0, 1.0 / 36.0, 1.0 / 36.0, 1.0 / 36.0,
    1.0 / 36.0, 1.0 / 36.0, 1.0 / 36.0, 1.0 / 36.0, 1.0 / 36.0, 1.0 / 36.0,
};

constexpr int opposite(int q) { return q == 0 ? 0 : (q % 2 == 1 ? q + 1 : q - 1); }

}  // namespace rbcal::solver::d3q19
