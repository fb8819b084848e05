#include "cli/mpi_split.hpp"

#ifdef FREESTAND_MPI
#include <nlohmann/json.hpp>
#include <mpi.h>

#include <sstream>
#include <string>

#include "fragility/serialize.hpp"
#endif

#include <cstdlib>

namespace freestand::cli {

#ifdef FREESTAND_MPI

MpiSplit::MpiSplit() {
    int initialised = 0;
    MPI_Initialized(&initialised);
    if (!initialised) {
        MPI_Init(nullptr, nullptr);
        owner_ = true;
    }
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSplit::~MpiSplit() {
    if (owner_) MPI_Finalize();
}

void MpiSplit::abort(int exit_code) const {
    MPI_Abort(MPI_COMM_WORLD, exit_code);
    std::exit(exit_code);  // MPI_Abort does not return; this keeps [[noreturn]] honest
}

std::vector<fragility::SampleResult> MpiSplit::gather_to_root(
    const std::vector<fragility::SampleResult>& mine) const {
    if (size_ == 1) return mine;
    // The samples travel as the shard files' JSON lines: lossless, and one format to test.
    std::string text;
    for (const auto& s : mine) text += fragility::to_json(s).dump() + "\n";
    int length = static_cast<int>(text.size());
    std::vector<int> lengths(static_cast<std::size_t>(size_)), offsets(static_cast<std::size_t>(size_));
    MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    std::string all;
    if (rank_ == 0) {
        int total = 0;
        for (int r = 0; r < size_; ++r) {
            offsets[static_cast<std::size_t>(r)] = total;
            total += lengths[static_cast<std::size_t>(r)];
        }
        all.resize(static_cast<std::size_t>(total));
    }
    MPI_Gatherv(text.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(),
                MPI_CHAR, 0, MPI_COMM_WORLD);
    std::vector<fragility::SampleResult> out;
    if (rank_ != 0) return out;
    std::istringstream in(all);
    std::string line;
    while (std::getline(in, line)) out.push_back(fragility::sample_from_json(nlohmann::json::parse(line)));
    return out;
}

#else

MpiSplit::MpiSplit() = default;
MpiSplit::~MpiSplit() = default;

void MpiSplit::abort(int exit_code) const { std::exit(exit_code); }

std::vector<fragility::SampleResult> MpiSplit::gather_to_root(
    const std::vector<fragility::SampleResult>& mine) const {
    return mine;
}

#endif

}  // namespace freestand::cli
