#pragma once
/// Named tolerances, one per meaning. Two equal values here are two different decisions: a
/// change to one must not move the other.
namespace freestand::core::tol {

/// Subtracted from a ratio before it is rounded up to whole units (steps, ranks, mm), so that a
/// ratio meant to be whole (0.84 x 25 = 21.000000000000004) is not rounded one unit up.
inline constexpr double rounding_guard = 1e-9;

/// Two damping ratios are the same damping within this (dimensionless): a spectrum's stated
/// damping against the one a method needs (5 % for the ASCE 4 and target spectra).
inline constexpr double damping_equal = 1e-9;

/// A duration meets a minimum within this, s: a record of exactly the minimum length, whose
/// (n - 1) dt lands a rounding below it, still meets it.
inline constexpr double duration_s = 1e-9;

/// A time step meets a maximum within this, s: a dt read back from a file or taken as a mean
/// of sample times lands an ulp above the 0.01 s it was written as, and is still that step.
inline constexpr double dt_s = 1e-12;

/// A frequency on a band's edge counts as inside within this, Hz: log-spaced check frequencies
/// land a rounding off the band's round-number edges (0.2 Hz, 25 Hz).
inline constexpr double band_edge_hz = 1e-12;

/// Relative tolerance of "the same value" for quantities of one scale (axis ticks against
/// their step, a grid's last point against its end).
inline constexpr double relative = 1e-9;

}  // namespace freestand::core::tol
