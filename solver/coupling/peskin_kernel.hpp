#pragma once
// Regularised delta functions of the immersed-boundary method, one-dimensional factors
// phi(r) of the tensor-product kernel, r in lattice spacings. All satisfy
// sum_j phi(r - j) = 1 and sum_j (r - j) phi(r - j) = 0 for every r, which make spreading
// conserve force and torque and make interpolation exact for linear fields.
//   2-point: the linear hat 1 - |r| (|r| < 1).
//   3-point: Roma, Peskin & Berger, J. Comput. Phys. 153 (1999) 509.
//   4-point: Peskin, Acta Numerica 11 (2002) 479, eq. 6.27 (the default); it also has
//            sum_j phi^2 = 3/8 and equal even and odd sums (1/2).
#include <cmath>
#include <stdexcept>
#include <string>

#include "solver/device/host_device.hpp"

namespace rbcal::solver {

enum class KernelKind { Linear2, Roma3, Peskin4 };

RBCAL_HD constexpr int kernel_support(KernelKind k) { return k == KernelKind::Linear2 ? 2 : (k == KernelKind::Roma3 ? 3 : 4); }

RBCAL_HD inline double kernel_weight(KernelKind k, double r) {
  const double a = fabs(r);
  switch (k) {
    case KernelKind::Linear2:
      return a < 1.0 ? 1.0 - a : 0.0;
    case KernelKind::Roma3:
      if (a <= 0.5) return (1.0 + sqrt(1.0 - 3.0 * a * a)) / 3.0;
      if (a <= 1.5) return (5.0 - 3.0 * a - sqrt(fmax(0.0, 1.0 - 3.0 * (1.0 - a) * (1.0 - a)))) / 6.0;
      return 0.0;
    case KernelKind::Peskin4:
      if (a <= 1.0) return (3.0 - 2.0 * a + sqrt(1.0 + 4.0 * a - 4.0 * a * a)) / 8.0;
      if (a <= 2.0) return (5.0 - 2.0 * a - sqrt(fmax(0.0, -7.0 + 12.0 * a - 4.0 * a * a))) / 8.0;
      return 0.0;
  }
  return 0.0;
}

inline std::string to_string(KernelKind k) {
  return k == KernelKind::Linear2 ? "linear2" : (k == KernelKind::Roma3 ? "roma3" : "peskin4");
}

inline KernelKind kernel_from_string(const std::string& name) {
  if (name == "linear2") return KernelKind::Linear2;
  if (name == "roma3") return KernelKind::Roma3;
  if (name == "peskin4") return KernelKind::Peskin4;
  throw std::invalid_argument("unknown kernel '" + name + "' (expected linear2, roma3 or peskin4)");
}

}  // namespace rbcal::solver
