#pragma once
/// Design spectra used as targets (METHODS.md s.8).
#include <vector>

#include "spectra/spectrum.hpp"

namespace freestand::spectra {

/// US NRC RG 1.60 at damping in {0.005, 0.02, 0.05, 0.07, 0.10}; other dampings interpolate
/// the factors on log damping. Horizontal or vertical control points.
Spectrum rg160(double pga_g, double damping, bool vertical, const std::vector<double>& frequency_hz);

/// ASCE 7 two-period spectrum (5%); periods in s.
Spectrum asce7(double sds_g, double sd1_g, double tl_s, const std::vector<double>& frequency_hz);

enum class Ec8Type { type1, type2 };
/// Eurocode 8 EN 1998-1 3.2.2.2 elastic spectrum; ground 'A'..'E'; any damping.
Spectrum ec8(double ag_g, Ec8Type type, char ground, double damping,
             const std::vector<double>& frequency_hz);

enum class Is1893Soil { rock, medium, soft };
/// IS 1893 (Part 1) 5% spectrum scaled by pga_g (Sa/g shape times PGA).
Spectrum is1893(double pga_g, Is1893Soil soil, const std::vector<double>& frequency_hz);

/// One-sided target PSD of RG 1.60 horizontal, SRP 3.7.1 App. A, m^2/s^3 per Hz at pga_g.
double rg160_target_psd(double f_hz, double pga_g);

}  // namespace freestand::spectra
