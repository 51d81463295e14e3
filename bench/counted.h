#pragma once
// A number type that counts the operations done on it. The step (kernels/step.h) is a
// template on its number type, so instantiating it with Counted counts exactly the
// floating-point work one realisation-step costs, from the source itself. It lives in the
// lane namespace so that the lane helpers find its overloads; include it before the kernels.

#include <cmath>
#include <cstdint>

#include "kernels/lane.h"

namespace caskdem::lane {

struct OperationCount {
  std::int64_t flops = 0;  // add, subtract, multiply, divide, square root
  std::int64_t other = 0;  // compare, select, min/max, abs, copysign, rounding, bit tricks
};

inline OperationCount& operation_count() {
  thread_local OperationCount count;
  return count;
}

struct Counted {
  double value = 0.0;
  Counted() = default;
  explicit Counted(double v) : value(v) {}
  static Counted load_aligned(const double* p) { return Counted(*p); }
};

inline Counted arithmetic(double v) {
  ++operation_count().flops;
  return Counted(v);
}
inline Counted operator+(Counted a, Counted b) { return arithmetic(a.value + b.value); }
inline Counted operator-(Counted a, Counted b) { return arithmetic(a.value - b.value); }
inline Counted operator*(Counted a, Counted b) { return arithmetic(a.value * b.value); }
inline Counted operator/(Counted a, Counted b) { return arithmetic(a.value / b.value); }
inline Counted operator-(Counted a) {
  ++operation_count().other;  // a sign flip is a bitwise operation
  return Counted(-a.value);
}

struct CountedMask {
  bool value;
};
inline CountedMask compare(bool v) {
  ++operation_count().other;
  return {v};
}
inline CountedMask operator<(Counted a, Counted b) { return compare(a.value < b.value); }
inline CountedMask operator<=(Counted a, Counted b) { return compare(a.value <= b.value); }
inline CountedMask operator>(Counted a, Counted b) { return compare(a.value > b.value); }
inline CountedMask operator>=(Counted a, Counted b) { return compare(a.value >= b.value); }
inline CountedMask operator==(Counted a, Counted b) { return compare(a.value == b.value); }
inline CountedMask operator!=(Counted a, Counted b) { return compare(a.value != b.value); }
inline CountedMask operator&&(CountedMask a, CountedMask b) { return compare(a.value && b.value); }
inline CountedMask operator||(CountedMask a, CountedMask b) { return compare(a.value || b.value); }
inline CountedMask operator!(CountedMask a) { return compare(!a.value); }


template <>
struct Traits<Counted> {
  using Mask = CountedMask;
  static constexpr std::size_t width = 1;
};

inline Counted other(double v) {
  ++operation_count().other;
  return Counted(v);
}
inline Counted select(CountedMask m, Counted a, Counted b) { return other(m.value ? a.value : b.value); }
inline Counted min(Counted a, Counted b) { return other(a.value < b.value ? a.value : b.value); }
inline Counted max(Counted a, Counted b) { return other(a.value > b.value ? a.value : b.value); }
inline Counted abs(Counted a) { return other(std::fabs(a.value)); }
inline Counted sqrt(Counted a) { return arithmetic(std::sqrt(a.value)); }
inline Counted copysign(Counted a, Counted b) { return other(std::copysign(a.value, b.value)); }
inline Counted nearbyint(Counted a) { return other(std::nearbyint(a.value)); }
inline Counted power_of_two(Counted k) {
  ++operation_count().flops;  // the add that places k in the mantissa; the shift is counted below
  return other(power_of_two(k.value));
}
inline CountedMask isfinite(Counted a) { return compare(std::isfinite(a.value)); }
inline bool any(CountedMask m) { return m.value; }
inline bool all(CountedMask m) { return m.value; }
inline void store(double* field, Counted v) { *field = v.value; }

}  // namespace caskdem::lane
