// One 3D step for the scalar reference and SIMD lanes (kernels/step3d.h): lanes of different
// realisations (released at different tilts and azimuths, one shaken in x and z, one sliding
// on low friction, one tipping over) advanced together in an xsimd batch of the build's default
// width give each realisation's scalar state bit for bit, as the 2D lanes do
// (tests/ensemble/test_agreement.cpp).

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>
#include <xsimd/xsimd.hpp>

#include "kernels/block3d.h"
#include "kernels/step3d.h"
#include "model/build3d.h"
#include "motion/component_set.h"
#include "motion/pair_intensity.h"
#include "sim/simulate3d.h"
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
                                              ContactState3D<Batch>{Batch(0.0), Batch(0.0), Batch(0.0), Batch(0.0)});
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

// The 3D block kernel (kernels/block3d.h) on every instruction set this machine has, in one
// block and in blocks of 5, each advanced in calls of 2048 steps, against each realisation run alone by the deterministic 3D code
// (sim/simulate3d.h): Northridge's three components (Rinaldi, compressed by sqrt 3, 8 s) at
// RotD50 PGA from 0.4 to 1.6 g, at incidences over [0, 180) degrees, on friction 0.2 and 0.6; every
// final state and result bit for bit, and the sliders' states against the scalar lanes'.
TEST(Cask3DLanes, BlocksGiveTheDeterministicRunsBitsOnEveryInstructionSet) {
  Case base = testing::one_third_model();
  base.model.friction_law = FrictionLaw::exponential;
  const CaskSpec3D spec{0.5 * base.cask.cylinder.diameter, base.cask.cylinder.height, base.model.section.rounding,
                        base.parameters.mass};
  const RealisationParameters nominal = nominal_parameters3d(spec, base.parameters);
  const Model3D model = build_model3d(base.model, spec, nominal);
  const double dt = model.model.time_step;
  const std::filesystem::path dir = std::filesystem::path(CASKDEM_SHARED_DIR) / "motions" / "three-component";
  const motion::ComponentSet set =
      motion::read_component_set(dir / "northridge1994_RSN1063_Rinaldi_H1_228.AT2",
                                 dir / "northridge1994_RSN1063_Rinaldi_H2_318.AT2", dir / "northridge1994_RSN1063_Rinaldi_UP.AT2");
  const double rotd50 = motion::pair_intensity(set.h1, set.h2).pga_rotd50;
  const auto component = [&](const motion::Record& r) {
    return motion::make_record_motion(motion::time_scaled(r, 1.0 / std::sqrt(3.0)));
  };
  const auto h1 = component(set.h1), h2 = component(set.h2), up = component(*set.vertical);
  const double duration = 8.0;
  const int steps = static_cast<int>(std::ceil(duration / dt));
  // One table per component at the unit scale; each realisation's scale is its own lane factor.
  std::vector<double> table_h1(steps), table_h2(steps), table_up(steps);
  for (int n = 0; n < steps; ++n) {
    table_h1[n] = h1->acceleration(n * dt);
    table_h2[n] = h2->acceleration(n * dt);
    table_up[n] = up->acceleration(n * dt);
  }
  struct Realisation {
    LaneParameters<double> lane;
    double incidence;
    RunResult3D alone;
  };
  std::vector<Realisation> realisations;
  for (int i = 0; i < 16; ++i) {
    RealisationParameters p = nominal;
    p.friction_static = i % 2 == 0 ? 0.6 : 0.2;
    p.friction_kinetic = 0.75 * p.friction_static;
    const double pga = (0.4 + 0.08 * i) * 9.80665;
    p.horizontal_scale = pga / rotd50;
    p.vertical_scale = p.horizontal_scale;
    Realisation r{lane_parameters3d(model, p), std::numbers::pi * ((7 * i) % 16) / 16.0, {}};
    // The deterministic run reads the same tables (a record motion of the table's samples at dt).
    r.alone = simulate3d(model, r.lane, rest_state3d(model, r.lane), {h1.get(), h2.get(), up.get(), r.incidence},
                         {duration, 0.0});
    realisations.push_back(std::move(r));
  }
  int tipped = 0, slid = 0, rocked = 0;
  for (const Realisation& r : realisations) {
    tipped += r.alone.summary.status == LaneStatus::tipped_over;
    slid += r.alone.summary.max_slide > 0.01;
    rocked += r.alone.summary.max_tilt_ratio > 0.1;
  }
  std::printf("of 16: %d tipped over, %d slid beyond 1 cm, %d rocked beyond 0.1 alpha\n", tipped, slid, rocked);
  EXPECT_GE(tipped, 2);
  EXPECT_GE(slid, 2);
  EXPECT_GE(rocked, 4);

  // Each block advanced in calls of 2048 steps (chunked = true), as an ensemble advances it, or
  // in one; the sliders' states of every lane kept for the comparison across instruction sets.
  using Sliders = std::vector<double>;
  const auto run_blocks = [&](InstructionSet isa, std::size_t block_size, bool chunked) {
    std::vector<Sliders> sliders_of(realisations.size());
    for (std::size_t first = 0; first < realisations.size(); first += block_size) {
      const std::size_t count = std::min(block_size, realisations.size() - first);
      LaneBlock3D block(static_cast<std::int64_t>(count));
      for (std::size_t l = 0; l < count; ++l) {
        const Realisation& r = realisations[first + l];
        const BodyState3D<double> rest = rest_state3d(model, r.lane);
        const ContactState3D<double> free[kContactSliders3D] = {};
        block.set_lane(static_cast<std::int64_t>(l), r.lane, rest, free, initial_response3d(r.lane, rest), r.incidence);
      }
      block.pad_from(0);
      const int chunk = chunked ? 2048 : steps;
      for (int done = 0; done < steps; done += chunk) {
        advance_block3d(isa, model.model, model.contacts, block, table_h1.data(), table_h2.data(), table_up.data(), 0,
                        std::min(chunk, steps - done));
      }
      for (std::size_t l = 0; l < count; ++l) {
        const RunResult3D& alone = realisations[first + l].alone;
        BodyState3D<double> body;
        ContactState3D<double> sliders[kContactSliders3D];
        Response3D<double> response;
        block.get_lane(static_cast<std::int64_t>(l), &body, sliders, &response);
        for (ContactState3D<double>& slider : sliders) {
          slider.for_each_field([&](double& v) { sliders_of[first + l].push_back(v); });
        }
        BodyState3D<double> expected = alone.final_state;
        std::vector<double> a, b;
        body.for_each_field([&](double& v) { a.push_back(v); });
        expected.for_each_field([&](double& v) { b.push_back(v); });
        const double max_tilt = 2.0 * std::asin(std::min(1.0, 0.5 * std::sqrt(response.max_axis_departure)));
        a.insert(a.end(), {response.status, max_tilt, response.max_slide, response.spin});
        b.insert(b.end(), {double(alone.summary.status), alone.summary.max_tilt, alone.summary.max_slide, alone.summary.spin});
        for (std::size_t k = 0; k < a.size(); ++k) {
          EXPECT_EQ(std::memcmp(&a[k], &b[k], sizeof(double)), 0)
              << instruction_set_name(isa) << ", blocks of " << block_size << ": realisation " << first + l << " value " << k
              << ": " << a[k] << " against " << b[k];
        }
      }
    }
    return sliders_of;
  };
  // The deterministic run keeps no sliders to compare with: the scalar lanes in one call are the
  // reference for them.
  const std::vector<Sliders> reference = run_blocks(InstructionSet::scalar, realisations.size(), false);
  int sliding_at_end = 0;
  for (const Sliders& s : reference) sliding_at_end += (s[0] != 0.0 || s[1] != 0.0);
  EXPECT_GE(sliding_at_end, 2) << "the sliders' comparison needs stretched springs";
  const auto check = [&](InstructionSet isa, std::size_t block_size) {
    const std::vector<Sliders> sliders = run_blocks(isa, block_size, true);
    for (std::size_t i = 0; i < sliders.size(); ++i) {
      EXPECT_EQ(std::memcmp(sliders[i].data(), reference[i].data(), reference[i].size() * sizeof(double)), 0)
          << instruction_set_name(isa) << ", blocks of " << block_size << ": realisation " << i << "'s sliders";
    }
  };
  for (InstructionSet isa : {InstructionSet::scalar, InstructionSet::sse2, InstructionSet::avx2, InstructionSet::avx512f}) {
    if (instruction_set_available(isa)) check(isa, realisations.size());
  }
  check(InstructionSet::automatic, 5);
}

}  // namespace
}  // namespace caskdem
