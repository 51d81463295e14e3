#include "ensemble/distributed.h"

#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <optional>

#include "core/error.h"
#include "ensemble/device_runner.h"
#include "ensemble/progress.h"
#include "ensemble/runner.h"

namespace caskdem {

namespace {

constexpr int kOutcomeFields = 12;  // index + the 11 fields of RealisationOutcome

void pack(std::int64_t index, const RealisationOutcome& o, std::vector<double>& out) {
  out.insert(out.end(), {double(index), double(o.status), o.max_abs_rotation, o.max_abs_slide, o.residual_slide,
                         o.max_uplift, o.impacts, o.end_time, o.instability_time, o.spin, o.max_slip,
                         o.residual_slip});
}

RealisationOutcome unpack(const double* p, std::int64_t* index) {
  *index = static_cast<std::int64_t>(p[0]);
  RealisationOutcome o;
  o.status = static_cast<LaneStatus>(static_cast<int>(p[1]));
  o.max_abs_rotation = p[2];
  o.max_abs_slide = p[3];
  o.residual_slide = p[4];
  o.max_uplift = p[5];
  o.impacts = p[6];
  o.end_time = p[7];
  o.instability_time = p[8];
  o.spin = p[9];
  o.max_slip = p[10];
  o.residual_slip = p[11];
  return o;
}

}  // namespace

bool launched_by_mpi() {
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE", "PMI_RANK", "MPI_LOCALNRANKS"}) {
    if (std::getenv(variable)) return true;
  }
  return false;
}

MpiSession::MpiSession(int* argc, char*** argv) {
  int provided = 0;
  // Outcomes reach MPI from whichever OpenMP thread finished a block, one call at a time.
  MPI_Init_thread(argc, argv, MPI_THREAD_SERIALIZED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  MPI_Comm node;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &node);
  MPI_Comm_rank(node, &local_rank_);
  MPI_Comm_free(&node);
}

MpiSession::~MpiSession() { MPI_Finalize(); }

void MpiSession::abort(const std::string& message) const {
  std::fprintf(stderr, "caskdem: rank %d of %d: error: %s\n", rank_, size_, message.c_str());
  std::fflush(stderr);
  MPI_Abort(MPI_COMM_WORLD, 1);
  std::abort();
}

ExecuteReport execute_ensemble_distributed(const EnsemblePlan& plan, const ExecuteOptions& options, const MpiSession& mpi) {
  const bool root = mpi.rank() == 0;
  // Every rank reads the checkpoint itself, so all agree on what is left to do.
  ResultFile file(plan, options);
  EnsembleResults& results = file.results();
  if (root) file.write(nullptr);

  // Contiguous slices, one per rank, of the pending realisations taken stripe by stripe in
  // turn (position 0 of every stripe, then position 1, ...): slices of the plain index order
  // would give one rank the weak stripes and another the strong ones, whose casks tip over
  // early and cost less, and the first would keep the others waiting.
  std::vector<std::int64_t> pending = results.pending();
  const std::int64_t per_stripe = plan.spec().realisations_per_stripe;
  std::stable_sort(pending.begin(), pending.end(), [per_stripe](std::int64_t a, std::int64_t b) {
    return a % per_stripe < b % per_stripe;
  });
  const auto total = static_cast<std::int64_t>(pending.size());
  const std::int64_t first = total * mpi.rank() / mpi.size();
  const std::int64_t last = total * (mpi.rank() + 1) / mpi.size();
  std::vector<std::int64_t> mine(pending.begin() + first, pending.begin() + last);
  std::sort(mine.begin(), mine.end());
  const MotionTables tables(plan,
                            options.device ? MotionTables::kDeviceBudgetBytes : MotionTables::kDefaultBudgetBytes);
  RunOptions run;
  run.isa = options.isa;
  run.threads = file.run().threads;
  run.lanes = plan.spec().block_lanes;
  std::optional<DeviceLanes> device_lanes;
  // Rounds of a few blocks' worth of realisations per thread: enough work between gathers to
  // keep every thread busy, often enough for progress and checkpoints. A GPU's rounds fill its
  // lanes several times over, so that few lanes wait while a round drains.
  std::size_t per_round = std::size_t(4) * file.run().threads * plan.spec().block_lanes;
  try {
    if (options.device) {
      device_lanes.emplace(plan, device_tables(plan, tables), *options.device);
      run.device = &*device_lanes;
      per_round = std::size_t(8) * static_cast<std::size_t>(device_lanes->lane_capacity());
      if (root) file.set_device_lanes(device_lanes->lane_capacity());
    }
  } catch (const InputError&) {
    throw;  // every rank's tables are the same: every rank fails alike, and rank 0 says why
  } catch (const std::exception& e) {
    mpi.abort(e.what());  // this rank's GPU alone: the others would wait for it for ever
  }
  int rounds = static_cast<int>((mine.size() + per_round - 1) / per_round);
  MPI_Allreduce(MPI_IN_PLACE, &rounds, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);

  Progress progress(results.size, results.completed_count(), root && options.progress);
  ExecuteReport report;
  std::vector<int> counts(mpi.size()), displacements(mpi.size());
  for (int round = 0; round < rounds; ++round) {
    const std::size_t begin = std::min(mine.size(), static_cast<std::size_t>(round) * per_round);
    const std::size_t end = std::min(mine.size(), begin + per_round);
    const std::vector<std::int64_t> these(mine.begin() + begin, mine.begin() + end);
    std::vector<double> packed;
    try {
      run_realisations(plan, tables, these, run,
                       [&](const std::vector<std::int64_t>& indices, const std::vector<RealisationOutcome>& outcomes) {
                         for (std::size_t k = 0; k < indices.size(); ++k) pack(indices[k], outcomes[k], packed);
                       });
    } catch (const std::exception& e) {
      mpi.abort(e.what());
    }
    int count = static_cast<int>(packed.size());
    MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    std::vector<double> gathered;
    if (root) {
      int offset = 0;
      for (int r = 0; r < mpi.size(); ++r) {
        displacements[r] = offset;
        offset += counts[r];
      }
      gathered.resize(offset);
    }
    MPI_Gatherv(packed.data(), count, MPI_DOUBLE, gathered.data(), counts.data(), displacements.data(), MPI_DOUBLE, 0,
                MPI_COMM_WORLD);
    if (!root) continue;
    for (std::size_t k = 0; k < gathered.size(); k += kOutcomeFields) {
      std::int64_t index = 0;
      const RealisationOutcome o = unpack(&gathered[k], &index);
      results.record(index, o, plan.stability_angle());
      ++report.realisations_run;
    }
    progress.update(results.completed_count());
    file.checkpoint_if_due();
  }
  if (root) {
    progress.finish();
    file.finish(report);
  }
  return report;
}

}  // namespace caskdem
