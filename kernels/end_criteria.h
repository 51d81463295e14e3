#pragma once
// How a lane's run ends (LaneStatus, kernels/model.h), shared by the 2D and 3D steps.

#include "kernels/host_device.h"
#include "kernels/lane.h"
#include "kernels/model.h"

namespace caskdem::kernels {

// Records the end of the lanes that stop in this step, their status and end time; the first
// matching criterion wins (a NaN state says nothing about tipping). Stopping is rare: the
// verdict is worked out only in a batch where some lane stops (a branch on the whole batch,
// so every lane's result is the same either way).
template <class T, class M>
CASKDEM_HOST_DEVICE inline void record_stop(const M& active, const M& finite, const M& tipped, const M& left_floor,
                                            const M& slid_off, const T& time, T& status, T& end_time) {
  using lane::broadcast;
  using lane::select;
  const auto stopping = active && (!finite || tipped || left_floor || slid_off);
  if (!lane::any(stopping)) return;
  T verdict = select(slid_off, broadcast<T>(double(LaneStatus::slid_off_pad)), broadcast<T>(0.0));
  verdict = select(left_floor, broadcast<T>(double(LaneStatus::left_floor)), verdict);
  verdict = select(tipped, broadcast<T>(double(LaneStatus::tipped_over)), verdict);
  verdict = select(!finite, broadcast<T>(double(LaneStatus::non_finite)), verdict);
  status = select(stopping, verdict, status);
  end_time = select(stopping, time, end_time);
}

}  // namespace caskdem::kernels
