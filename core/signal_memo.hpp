// Signals (core/signal.hpp) sampled with a memo of the last time asked for: an evaluation at
// the same time as the one before it reads the values kept then instead of evaluating the
// signals again. RK4 asks twice at each time (its two middle stages share t + h/2, a step's
// last stage and the next step's first share t + h), so its inputs cost half; a constant
// component is read once, when the memo is made. The values are the signals' own, bit for
// bit: the memo is keyed on the time's bits, and a signal depends on the time only.
// Not here: the signals (owned by the model, which must outlive the memo), anything that
// depends on the state.
#pragma once

#include <array>
#include <bit>
#include <cstdint>
#include <limits>

#include "core/math.hpp"
#include "core/signal.hpp"

namespace tribo {

// True when a and b are the same double, bit for bit (so 0 and -0 differ, NaN never matches
// a time).
inline bool sameTime(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// Three signals, one vector (a force, a torque, a surface velocity).
class SignalVectorMemo {
 public:
  SignalVectorMemo() = default;
  explicit SignalVectorMemo(const std::array<Signal, 3>& signals) : signals_(&signals) {
    for (int k = 0; k < 3; ++k) {
      if (signals[k].kind() == Signal::Kind::kConstant)
        value_[k] = signals[k].value(0.0);
      else
        varying_[varying_count_++] = k;
    }
    zero_ = signals[0].isZero() && signals[1].isZero() && signals[2].isZero();
  }
  // Every component the constant 0.
  bool zero() const { return zero_; }
  // The components at time t.
  const Vec3& at(double t) {
    if (varying_count_ == 0 || sameTime(t, time_)) return value_;
    time_ = t;
    for (int i = 0; i < varying_count_; ++i)
      value_[varying_[i]] = (*signals_)[varying_[i]].value(t);
    return value_;
  }

 private:
  const std::array<Signal, 3>* signals_ = nullptr;
  Vec3 value_ = Vec3::Zero();
  double time_ = std::numeric_limits<double>::quiet_NaN();
  std::array<int, 3> varying_{};  // the components that are not constants
  int varying_count_ = 0;
  bool zero_ = true;
};

// One signal's value and, when asked for at construction, its derivative.
class SignalMemo {
 public:
  SignalMemo() = default;
  SignalMemo(const Signal& signal, bool with_derivative)
      : signal_(&signal), with_derivative_(with_derivative) {}
  struct Sample {
    double value = 0.0;
    double derivative = 0.0;  // 0 unless asked for
  };
  const Sample& at(double t) {
    if (sameTime(t, time_)) return sample_;
    time_ = t;
    sample_.value = signal_->value(t);
    if (with_derivative_) sample_.derivative = signal_->derivative(t);
    return sample_;
  }

 private:
  const Signal* signal_ = nullptr;
  bool with_derivative_ = false;
  Sample sample_;
  double time_ = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace tribo
