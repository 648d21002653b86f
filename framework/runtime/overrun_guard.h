#pragma once

namespace fitfeel {

// What the device receives around a missed deadline in real time (the overrun policy):
// zero, then a ramp back to the full wrench.
//
// A tick that wakes more than one period after its deadline follows an interval in which the
// device held the previous force for two periods or more: a sampled spring is passive only while
// b > K T / 2 (Colgate & Schenkel), so doubling T halves the stiffness the device renders
// passively, and the late tick's wrench is the one that rests on the longest hold. Sending zero is
// passive whatever the contact; holding the stale force (what the hardware does by itself) or
// sending the late wrench is not. The return to full force is ramped over `ramp_ticks` (20 at
// 1 kHz: 20 ms) so that it comes back in steps of 5 %, not as a knock the hand feels, and well
// within a hand's reaction time (100-150 ms), so the contact is back before the user reacts.
// Not for the virtual clock, which has no deadline. Per run (RunState); noexcept, no allocation.
class OverrunGuard {
 public:
  static constexpr int kRampTicks = 20;

  // The factor for this tick's device wrench, given how late the tick woke after its deadline
  // (s) and the period (s).
  double Factor(double lateness, double period) noexcept {
    if (lateness > period) {
      ++overruns_;
      ramp_ = 0;
      return 0.0;
    }
    if (ramp_ < kRampTicks) {
      ++ramp_;
      return static_cast<double>(ramp_) / kRampTicks;
    }
    return 1.0;
  }
  unsigned long long overruns() const { return overruns_; }
  void Reset() noexcept { *this = OverrunGuard{}; }

 private:
  int ramp_ = kRampTicks;  // ticks since the last overrun, up to the ramp's end
  unsigned long long overruns_ = 0;
};

}  // namespace fitfeel
