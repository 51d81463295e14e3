// One 3D step for the scalar reference and SIMD lanes (kernels/step3d.h): lanes of different
// realisations (released at different tilts and azimuths, one shaken in x and z, one sliding
// on low friction, one tipping over) advanced together in an xsimd batch of the build's default
// width give each realisation's scalar state bit for bit, as the 2D lanes do
// (tests/ensemble/test_agreement.cpp).

#include <cstring>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>
#include <xsimd/xsimd.hpp>

#include "kernels/step3d.h"
#include "model/build3d.h"
#include "support/paper_cases.h"

namespace caskdem {
namespace {

using Batch = xsimd::batch<double>;
constexpr std::size_t kWidth = Batch::size;

// Field by field, lane l of the batch state from realisation l's scalar state.
template <class Wide, class Narrow>
Wide to_batch(const std::vector<Narrow>& lanes) {
  Wide wide;
  int field = 0;
  wide.for_each_field([&](Batch& value) {
    alignas(64) double values[kWidth];
    for (std::size_t l = 0; l < kWidth; ++l) {
      Narrow copy = lanes[l];
      int k = 0;
      copy.for_each_field([&](double& v) {
        if (k++ == field) values[l] = v;
      });
    }
    value = Batch::load_aligned(values);
    ++field;
  });
  return wide;
}

TEST(Cask3DLanes, EveryLaneEqualsItsScalarRunBitForBit) {
  Case base = testing::one_third_model();
  base.model.friction_law = FrictionLaw::exponential;
  CaskSpec3D spec{0.5 * base.cask.cylinder.diameter, base.cask.cylinder.height, base.model.section.rounding,
                  base.parameters.mass};
  const RealisationParameters nominal = nominal_parameters3d(spec, base.parameters);
  const Model3D model = build_model3d(base.model, spec, nominal);
  const double alpha = model.model.stability_angle;

  // Up to 8 realisations; the batch holds kWidth of them at a time.
  struct Setup {
    double friction, tilt, azimuth, shake_x, shake_z;
  };
  const std::vector<Setup> setups = {{0.6, 0.5 * alpha, 0.0, 0.0, 0.0},  {0.6, 0.8 * alpha, 1.1, 0.0, 0.0},
                                     {0.1, 0.0, 0.0, 3.0, 0.0},          {0.6, 0.0, 0.0, 2.5, 2.0},
                                     {0.6, 0.3 * alpha, 2.5, 1.0, -1.5}, {0.3, 0.6 * alpha, -0.7, 0.0, 1.0},
                                     {0.6, 2.0 * alpha, 0.4, 0.0, 0.0},  {0.6, 0.2 * alpha, 3.0, 3.5, 3.5}};
  const int steps = 60000;  // about 1 s
  int tipped = 0, slid = 0, rocked = 0;
  for (std::size_t first = 0; first < setups.size(); first += kWidth) {
    std::vector<LaneParameters<double>> lanes;
    std::vector<BodyState3D<double>> bodies;
    std::vector<Response3D<double>> responses;
    for (std::size_t l = 0; l < kWidth; ++l) {
      const Setup& s = setups[(first + l) % setups.size()];
      RealisationParameters p = nominal;
      p.friction_static = s.friction;
      p.friction_kinetic = 0.75 * s.friction;
      lanes.push_back(lane_parameters3d(model, p));
      bodies.push_back(s.tilt > 0.0 ? tilted_state3d(model, lanes.back(), s.tilt, s.azimuth) : rest_state3d(model, lanes.back()));
      responses.push_back(initial_response3d(lanes.back(), bodies.back()));
    }
    // The scalar runs.
    std::vector<BodyState3D<double>> scalar_bodies = bodies;
    std::vector<Response3D<double>> scalar_responses = responses;
    for (std::size_t l = 0; l < kWidth; ++l) {
      const Setup& s = setups[(first + l) % setups.size()];
      std::vector<ContactState3D<double>> points(kContactSliders3D, ContactState3D<double>{});
      for (int n = 0; n < steps; ++n) {
        const double t = n * model.model.time_step;
        kernels::step3d<FrictionLaw::exponential>(model.model, model.contacts, lanes[l], s.shake_x * std::sin(7.0 * t), 0.0,
                                                  s.shake_z * std::sin(5.0 * t), t, scalar_bodies[l], points.data(),
                                                  scalar_responses[l]);
      }
    }
    for (std::size_t l = 0; l < kWidth && first + l < setups.size(); ++l) {
      tipped += scalar_responses[l].status == double(LaneStatus::tipped_over);
      slid += scalar_responses[l].max_slide > 1e-3;
      rocked += scalar_responses[l].max_uplift > 1e-3;
    }
    // The same realisations as one batch.
    const LaneParameters<Batch> p = to_batch<LaneParameters<Batch>>(lanes);
    const auto batch_of = [&](auto&& per_lane) {
      alignas(64) double values[kWidth];
      for (std::size_t l = 0; l < kWidth; ++l) values[l] = per_lane(l);
      return Batch::load_aligned(values);
    };
    BodyState3D<Batch> body = to_batch<BodyState3D<Batch>>(bodies);
    Response3D<Batch> response = to_batch<Response3D<Batch>>(responses);
    std::vector<ContactState3D<Batch>> points(kContactSliders3D,
                                              ContactState3D<Batch>{Batch(0.0), Batch(0.0), Batch(0.0)});
    for (int n = 0; n < steps; ++n) {
      const double t = n * model.model.time_step;
      const Batch x = batch_of([&](std::size_t l) { return setups[(first + l) % setups.size()].shake_x * std::sin(7.0 * t); });
      const Batch z = batch_of([&](std::size_t l) { return setups[(first + l) % setups.size()].shake_z * std::sin(5.0 * t); });
      kernels::step3d<FrictionLaw::exponential>(model.model, model.contacts, p, x, Batch(0.0), z, Batch(t), body,
                                                points.data(), response);
    }
    for (std::size_t l = 0; l < kWidth; ++l) {
      int field = 0;
      BodyState3D<Batch> wide = body;
      BodyState3D<double> narrow = scalar_bodies[l];
      std::vector<double> a, b;
      wide.for_each_field([&](Batch& v) { a.push_back(v.get(l)); });
      narrow.for_each_field([&](double& v) { b.push_back(v); });
      for (; field < static_cast<int>(a.size()); ++field) {
        EXPECT_EQ(std::memcmp(&a[field], &b[field], sizeof(double)), 0) << "lane " << first + l << " body field " << field;
      }
      Response3D<Batch> wide_r = response;
      Response3D<double> narrow_r = scalar_responses[l];
      a.clear();
      b.clear();
      wide_r.for_each_field([&](Batch& v) { a.push_back(v.get(l)); });
      narrow_r.for_each_field([&](double& v) { b.push_back(v); });
      for (std::size_t k = 0; k < a.size(); ++k) {
        EXPECT_EQ(std::memcmp(&a[k], &b[k], sizeof(double)), 0) << "lane " << first + l << " response field " << k;
      }
    }
  }
  // The comparison proves something only if the lanes did different things.
  EXPECT_GE(tipped, 1);
  EXPECT_GE(slid, 1);
  EXPECT_GE(rocked, 3);
}

}  // namespace
}  // namespace caskdem
