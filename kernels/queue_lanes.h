#pragma once
// Lanes that refill themselves from a queue: the ensemble on a GPU, one realisation per
// thread (kernels/cuda/), and the same code on the host in its place (kernels/lane_device.h).
//
// Each lane runs the scalar step (kernels/step.h, kernels/step3d.h with T = double: the CPU's
// reference instantiation) for a launch's number of steps. When its realisation ends, because
// the cask stopped or its run is over, the lane writes the realisation's state to the list of
// finished ones and claims the next pending realisation from a ring that the host fills between
// launches: no lane idles while a realisation waits. A realisation's result depends on nothing
// but its own state and the table motion at its own steps, so it is the same on any lane, in
// any launch, and the same as the CPU's.
//
// Every array is a set of rows, one per field, each as long as the capacity (structure of
// arrays: field f of column c is data[f * stride + c], so that neighbouring threads read
// neighbouring addresses). A realisation's record is its lane parameters, body state and
// response (and in 3D its incidence's cosine and sine), as the host built them from the plan
// (src/ensemble/lane_io.h); a lane also keeps its spring-sliders, its clock (the step it is
// at), where it reads the tables, how many steps its run has, which queue position it holds
// and how many steps it advanced.
//
// Claims. Queue position k lives in ring slot k mod the ring's capacity; claim() returns the
// next position below the host's `tail` (an atomic add on the GPU) or -1, and finish() the
// next row of the finished list. The host fills a position only once the lane that held its
// slot before has claimed it, and reads the finished rows after the launch.

#include <cstdint>
#include <type_traits>

#include "kernels/host_device.h"
#include "kernels/lane_state.h"
#include "kernels/lane_state3d.h"
#include "kernels/model.h"
#include "kernels/model3d.h"
#include "kernels/step.h"
#include "kernels/step3d.h"

namespace caskdem {

// Rows of doubles (or of indices) over `stride` columns.
template <class Number>
struct Rows {
  Number* data = nullptr;
  std::int64_t stride = 0;
  CASKDEM_HOST_DEVICE Number& operator()(int row, std::int64_t column) const { return data[row * stride + column]; }
};

// The index rows of each array.
enum LaneIndexRow : int { kTableIndexRow = 0, kEndStepRow = 1, kHeldRow = 2, kBusyStepsRow = 3, kLaneIndexRows = 4 };
enum PendingIndexRow : int { kTableOffsetRow = 0, kStepsRow = 1, kPendingIndexRows = 2 };
enum FinishedIndexRow : int { kPositionRow = 0, kFinishedIndexRows = 1 };

// The sizes of a queued run: which cask, how many rows each array has, and the capacities.
struct QueueShape {
  int dimensions = 2;         // 2: the planar cask; 3: the cask in 3D
  int contact_count = 0;      // corners (2D) or spring-sliders (3D)
  std::int64_t lanes = 0;     // lanes advanced at once (GPU threads)
  std::int64_t pending = 0;   // the ring of realisations waiting for a lane
  std::int64_t finished = 0;  // finished rows a launch may write: lanes + pending

  CASKDEM_HOST_DEVICE int body_rows() const {
    return dimensions == 3 ? BodyState3D<double>::field_count : BodyState<double>::field_count;
  }
  CASKDEM_HOST_DEVICE int response_rows() const {
    return dimensions == 3 ? Response3D<double>::field_count : Response<double>::field_count;
  }
  CASKDEM_HOST_DEVICE int incidence_rows() const { return dimensions == 3 ? 2 : 0; }
  // A realisation's record: parameters, body, response, incidence.
  CASKDEM_HOST_DEVICE int record_rows() const {
    return LaneParameters<double>::field_count + body_rows() + response_rows() + incidence_rows();
  }
  CASKDEM_HOST_DEVICE int contact_rows() const {
    return contact_count * (dimensions == 3 ? ContactState3D<double>::field_count : CornerState<double>::field_count);
  }
  // A lane: its record, its spring-sliders, its clock.
  CASKDEM_HOST_DEVICE int lane_rows() const { return record_rows() + contact_rows() + 1; }
};

// Where the arrays of a queued run lie (on the GPU: device addresses).
struct QueueView {
  QueueShape shape;
  Rows<double> lanes;                 // lane_rows() x shape.lanes
  Rows<std::int64_t> lane_index;      // kLaneIndexRows x shape.lanes
  Rows<double> pending;               // record_rows() x shape.pending
  Rows<std::int64_t> pending_index;   // kPendingIndexRows x shape.pending
  Rows<double> finished;              // record_rows() x shape.finished
  Rows<std::int64_t> finished_index;  // kFinishedIndexRows x shape.finished
  const double* table[3] = {};        // every motion's whole run, end to end: H1, H2, vertical (null: absent)
};

// The planar cask's realisation as a lane holds it.
struct PlanarLane {
  LaneParameters<double> parameters;
  BodyState<double> body;
  Response<double> response;
  CornerState<double> contacts[kMaxCorners];

  template <class F>
  CASKDEM_HOST_DEVICE void for_each_record_field(F&& f) {
    parameters.for_each_field(f);
    body.for_each_field(f);
    response.for_each_field(f);
  }
  // One step at table row `at`, as the CPU's block kernel takes it (kernels/block_kernel.h):
  // the planar cask has no vertical component.
  template <FrictionLaw Law>
  CASKDEM_HOST_DEVICE void step(const Model& model, const Contacts3D*, const QueueView& q, std::int64_t at,
                                double time) {
    kernels::step<Law>(model, parameters, q.table[0][at], 0.0, time, body, contacts, response);
  }
};

// The cask in 3D, at its incidence (the direction of H1 in the floor plane).
struct SpatialLane {
  LaneParameters<double> parameters;
  BodyState3D<double> body;
  Response3D<double> response;
  double incidence_cos, incidence_sin;
  ContactState3D<double> contacts[kContactSliders3D];

  template <class F>
  CASKDEM_HOST_DEVICE void for_each_record_field(F&& f) {
    parameters.for_each_field(f);
    body.for_each_field(f);
    response.for_each_field(f);
    f(incidence_cos);
    f(incidence_sin);
  }
  // As kernels/block3d_kernel.h: H1 and H2 turned by the incidence, absent components zero.
  template <FrictionLaw Law>
  CASKDEM_HOST_DEVICE void step(const Model& model, const Contacts3D* spatial, const QueueView& q, std::int64_t at,
                                double time) {
    const double a1 = q.table[0][at];
    const double a2 = q.table[1] ? q.table[1][at] : 0.0;
    const double vertical = q.table[2] ? q.table[2][at] : 0.0;
    const double table_x = incidence_cos * a1 - incidence_sin * a2;
    const double table_z = incidence_sin * a1 + incidence_cos * a2;
    kernels::step3d<Law>(model, *spatial, parameters, table_x, vertical, table_z, time, body, contacts, response);
  }
};

// Advances lane `lane` by up to `steps` steps, refilling it as its realisations end.
// Claim: () -> the next queue position, or -1; Finish: () -> the next finished row.
template <class Lane, FrictionLaw Law, class Claim, class Finish>
CASKDEM_HOST_DEVICE inline void run_queued_lane(const Model& model, const Contacts3D* spatial, const QueueView& q,
                                                std::int64_t lane, int steps, Claim&& claim, Finish&& finish) {
  Lane s;
  double clock = 0.0;
  std::int64_t at = 0, end = 0;
  std::int64_t held = q.lane_index(kHeldRow, lane);
  const int contact_count = q.shape.contact_count;
  auto take = [&]() -> bool {
    held = claim();
    if (held < 0) return false;
    const std::int64_t slot = held % q.shape.pending;
    int row = 0;
    s.for_each_record_field([&](double& v) { v = q.pending(row++, slot); });
    for (int k = 0; k < contact_count; ++k) s.contacts[k] = {};
    clock = 0.0;
    at = q.pending_index(kTableOffsetRow, slot);
    end = q.pending_index(kStepsRow, slot);
    return true;
  };
  if (held < 0) {
    if (!take()) return;
  } else {
    int row = 0;
    s.for_each_record_field([&](double& v) { v = q.lanes(row++, lane); });
    for (int k = 0; k < contact_count; ++k) s.contacts[k].for_each_field([&](double& v) { v = q.lanes(row++, lane); });
    clock = q.lanes(row, lane);
    at = q.lane_index(kTableIndexRow, lane);
    end = q.lane_index(kEndStepRow, lane);
  }
  const double dt = model.time_step;
  std::int64_t busy = 0;
  for (int n = 0; n < steps; ++n) {
    // Ended: stopped (frozen since), or ran its whole run; the host finishes it (src/ensemble/lane_io.h).
    if (s.response.status != 0.0 || clock >= static_cast<double>(end)) {
      const std::int64_t out = finish();
      int row = 0;
      s.for_each_record_field([&](double& v) { q.finished(row++, out) = v; });
      q.finished_index(kPositionRow, out) = held;
      if (!take()) break;
    }
    s.template step<Law>(model, spatial, q, at, clock * dt);
    clock = clock + 1.0;
    ++at;
    ++busy;
  }
  q.lane_index(kHeldRow, lane) = held;
  q.lane_index(kBusyStepsRow, lane) += busy;
  if (held < 0) return;
  int row = 0;
  s.for_each_record_field([&](double& v) { q.lanes(row++, lane) = v; });
  for (int k = 0; k < contact_count; ++k) s.contacts[k].for_each_field([&](double& v) { q.lanes(row++, lane) = v; });
  q.lanes(row, lane) = clock;
  q.lane_index(kTableIndexRow, lane) = at;
  q.lane_index(kEndStepRow, lane) = end;
}

// Calls visit(std::type_identity<Lane>, std::integral_constant<FrictionLaw, Law>) for the lane
// kind of `dimensions` and the friction law: each device's one switch over what it instantiates.
template <class Visit>
inline void visit_lane_kind(int dimensions, FrictionLaw law, Visit&& visit) {
  auto with_law = [&](auto lane) {
    switch (law) {
      case FrictionLaw::constant: visit(lane, std::integral_constant<FrictionLaw, FrictionLaw::constant>{}); break;
      case FrictionLaw::static_kinetic:
        visit(lane, std::integral_constant<FrictionLaw, FrictionLaw::static_kinetic>{});
        break;
      case FrictionLaw::exponential:
        visit(lane, std::integral_constant<FrictionLaw, FrictionLaw::exponential>{});
        break;
      case FrictionLaw::tabulated: visit(lane, std::integral_constant<FrictionLaw, FrictionLaw::tabulated>{}); break;
    }
  };
  if (dimensions == 3) {
    with_law(std::type_identity<SpatialLane>{});
  } else {
    with_law(std::type_identity<PlanarLane>{});
  }
}

}  // namespace caskdem
