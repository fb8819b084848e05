#pragma once
/// A result about each rocking edge of a planar block, and the edge whose result governs
/// (docs/methods.md s.1: the block rocks about its left or right edge).
#include "block/block.hpp"

namespace freestand::block {

/// One value per edge. Each result type says by which rule governing_edge is chosen.
template <class T>
struct EdgePair {
    T left;
    T right;
    Edge governing_edge = Edge::right;
    const T& governing() const { return governing_edge == Edge::left ? left : right; }
};

}  // namespace freestand::block
