#pragma once
// Ensembles across MPI ranks (Open MPI from Debian). `mpirun -n K caskdem ensemble ...`
// splits the pending realisations into K contiguous slices (of the realisations taken
// stripe by stripe in turn, so that every rank gets every intensity level); each rank runs
// its slice on the threaded SIMD engine, or on one GPU of its node (its local rank's), in
// rounds, and after each round rank 0 gathers the outcomes, reports progress for all ranks and
// checkpoints the one result file.
//
// Rank 0 gathers rather than every rank writing hyperslabs with parallel HDF5: an outcome is
// 9 doubles (72 bytes) and costs seconds of computing, so the traffic is negligible; a single
// writer keeps the atomic-rename checkpoint (the file on disk is always complete and
// resumable) and needs only the serial HDF5 library. Every realisation's result is computed
// exactly as on one machine, so the file equals the single-process one bit for bit.
//
// A rank that fails prints its error and aborts the job (MPI_Abort); the file holds the last
// checkpoint, and `--resume` continues it, under MPI or not.

#include "ensemble/execute.h"

namespace caskdem {

// True when this process was started by an MPI launcher (mpirun/srun set these variables);
// the single-machine path then never initialises MPI.
bool launched_by_mpi();

// MPI_Init_thread / MPI_Finalize around a scope; rank and size of MPI_COMM_WORLD.
class MpiSession {
 public:
  MpiSession(int* argc, char*** argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }
  int local_rank() const { return local_rank_; }  // among the ranks on this node: which of its GPUs to take
  [[noreturn]] void abort(const std::string& message) const;

 private:
  int rank_ = 0;
  int size_ = 1;
  int local_rank_ = 0;
};

// Runs the ensemble over all ranks; the report (and the file) are complete on rank 0.
ExecuteReport execute_ensemble_distributed(const EnsemblePlan& plan, const ExecuteOptions& options, const MpiSession& mpi);

}  // namespace caskdem
