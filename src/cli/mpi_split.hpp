#pragma once
/// The MPI share of a fragility run (build option FREESTAND_MPI): rank r of P computes the
/// samples whose global index is r mod P and rank 0 gathers them, so `mpirun -n P freestand
/// fragility ...` writes the same bytes as one process. Without MPI, or outside mpirun, one
/// rank of one.
#include <vector>

#include "fragility/fragility.hpp"

namespace freestand::cli {

class MpiSplit {
  public:
    MpiSplit();   ///< MPI_Init when built with MPI and not yet initialised
    ~MpiSplit();  ///< MPI_Finalize if this object initialised it
    MpiSplit(const MpiSplit&) = delete;
    MpiSplit& operator=(const MpiSplit&) = delete;

    int rank() const { return rank_; }
    int size() const { return size_; }
    /// Ends every rank with this exit code (MPI_Abort): a rank that fails alone would leave
    /// the others waiting in the gather for ever. Without MPI, std::exit.
    [[noreturn]] void abort(int exit_code) const;
    /// Every rank's samples on rank 0 (others get an empty vector); the input as is with one rank.
    std::vector<fragility::SampleResult> gather_to_root(
        const std::vector<fragility::SampleResult>& mine) const;

  private:
    int rank_ = 0;
    int size_ = 1;
    [[maybe_unused]] bool owner_ = false;  // MPI was initialised here (read with MPI only)
};

}  // namespace freestand::cli
