#pragma once
/// The runs of one level, kept while the level grows (docs/methods.md s.6 step 4). Set k's run
/// under a level's model and excitation does not depend on how many sets are in use, so a level
/// grown from N to N + 30 sets simulates only the 30 new ones and its statistics keep the bits
/// of a run that simulated all N + 30 at once.
#include <cstddef>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "assess/case.hpp"
#include "dynamics/body3d.hpp"
#include "dynamics/flexible.hpp"
#include "dynamics/simulate.hpp"

namespace freestand::assess {

/// Set k's run, when made, at element k.
template <class T>
using RunTable = std::vector<std::optional<T>>;

class LevelRuns {
  public:
    /// The table of the model at `slot` in direction d, at least n long. Take it before the runs
    /// start: the threads then write distinct elements of a table that no longer grows.
    RunTable<dynamics::Summary>& rigid(Direction d, int slot, std::size_t n) {
        return sized(rigid_[{d, slot}], n);
    }
    RunTable<dynamics::FlexibleSummary>& flexible(Direction d, int slot, std::size_t n) {
        return sized(flexible_[{d, slot}], n);
    }
    /// Peak |u| of the biaxial block (one model per level: the sliding bound).
    RunTable<double>& biaxial(std::size_t n) { return sized(biaxial_, n); }
    /// The 3D body at the sliding (slot 0) or the rocking (slot 1) bound.
    RunTable<dynamics::Body3dSummary>& body3d(int slot, std::size_t n) {
        return sized(body3d_[slot], n);
    }

  private:
    template <class T>
    static RunTable<T>& sized(RunTable<T>& t, std::size_t n) {
        if (t.size() < n) t.resize(n);
        return t;
    }
    std::map<std::pair<Direction, int>, RunTable<dynamics::Summary>> rigid_;
    std::map<std::pair<Direction, int>, RunTable<dynamics::FlexibleSummary>> flexible_;
    RunTable<double> biaxial_;
    std::map<int, RunTable<dynamics::Body3dSummary>> body3d_;
};

/// table[k], made by `make` on first use; `make` alone without a table.
template <class T, class Make>
T remembered(RunTable<T>* table, std::size_t k, Make&& make) {
    if (!table) return make();
    std::optional<T>& run = (*table)[k];
    if (!run) run = make();
    return *run;
}

}  // namespace freestand::assess
