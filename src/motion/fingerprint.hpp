#pragma once
/// The exact description of a generation request (targets, options, seed records and the
/// generator's own version), written as bytes for a content-addressed cache key: two requests
/// with the same fingerprint generate the same set, bit for bit.
#include "core/bytes.hpp"
#include "motion/motion.hpp"

namespace freestand::motion {

/// The generator's version: part of every cache key. Raise it whenever a change to the
/// generation or matching would change a generated set (tests/motion/test_fingerprint.cpp
/// holds the digest of a reference set and fails until it is raised).
inline constexpr const char* generator_version = "1";

/// Appends every field of the targets and the options that the generated set depends on.
void append_fingerprint(core::ByteWriter& w, const TargetSet& targets);
/// Appends what else the set's bits depend on: the build (core::build_identity()) and the
/// libraries loaded at run time (FFTW, the C library's maths).
void append_build_fingerprint(core::ByteWriter& w);
void append_fingerprint(core::ByteWriter& w, const GenerateOptions& options);

/// A record's fields, exactly; read_record is its inverse.
void write_record(core::ByteWriter& w, const core::Record& r);
core::Record read_record(core::ByteReader& r);

/// An acceptance report's fields, exactly; read_acceptance is its inverse.
void write_acceptance(core::ByteWriter& w, const Acceptance& a);
Acceptance read_acceptance(core::ByteReader& r);

}  // namespace freestand::motion
