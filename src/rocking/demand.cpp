#include "rocking/demand.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "core/errors.hpp"

namespace freestand::rocking {

namespace {

const spectra::Spectrum& checked(const spectra::Spectrum& s) {
    if (s.frequency_hz.empty() || s.frequency_hz.size() != s.psa_g.size())
        throw InputError(SourceLocation{"", 0, "spectrum"},
                         fmt::format("spectrum \"{}\" has {} frequencies and {} PSA values; "
                                     "expected the same number, at least one",
                                     s.label, s.frequency_hz.size(), s.psa_g.size()));
    return s;
}

}  // namespace

double DampedDemand::psa_g(double f_hz) const {
    double a = lo.psa_at(f_hz);
    if (weight_hi > 0.0) a = std::pow(a, 1.0 - weight_hi) * std::pow(hi.psa_at(f_hz), weight_hi);
    return factor * a;
}

double ec8_eta(double damping) {
    require_in_range(damping, 0.0, 1.0, SourceLocation{"", 0, "damping"}, true, false);
    return std::max(0.55, std::sqrt(10.0 / (5.0 + 100.0 * damping)));
}

DampedSpectra::DampedSpectra(std::vector<spectra::Spectrum> set) : set_(std::move(set)) {
    if (set_.empty())
        throw InputError(SourceLocation{"", 0, "spectrum"},
                         "no spectrum given; expected at least one damping");
    for (const auto& s : set_) checked(s);
    std::sort(set_.begin(), set_.end(),
              [](const auto& a, const auto& b) { return a.damping < b.damping; });
    for (std::size_t i = 1; i < set_.size(); ++i)
        if (set_[i].damping == set_[i - 1].damping)
            throw InputError(SourceLocation{"", 0, "damping"},
                             fmt::format("two spectra at damping {} (\"{}\", \"{}\"); expected "
                                         "distinct dampings",
                                         set_[i].damping, set_[i - 1].label, set_[i].label));
    std::vector<std::string> labels;
    for (const auto& s : set_) labels.push_back(s.label);
    label_ = fmt::format("{}", fmt::join(labels, "; "));
}

DampedSpectra::DampedSpectra(std::function<spectra::Spectrum(double)> generator, std::string label)
    : generator_(std::move(generator)), label_(std::move(label)) {}

DampedDemand DampedSpectra::at(double damping) const {
    require_in_range(damping, 0.0, 1.0, SourceLocation{"", 0, "damping"}, false, false);
    DampedDemand d;
    if (generator_) {
        d.lo = checked(generator_(damping));
        d.note = fmt::format("generated at {:.4g}% damping", 100.0 * damping);
        return d;
    }
    const auto above = std::lower_bound(set_.begin(), set_.end(), damping,
                                        [](const auto& s, double x) { return s.damping < x; });
    if (above != set_.end() && above->damping == damping) {
        d.lo = *above;
        d.note = fmt::format("spectrum at {:.4g}% damping", 100.0 * damping);
    } else if (above == set_.begin() || above == set_.end()) {
        const auto& near = above == set_.end() ? set_.back() : set_.front();
        d.lo = near;
        d.factor = ec8_eta(damping) / ec8_eta(near.damping);
        d.note = fmt::format("{:.4g}% damping scaled from the {:.4g}% spectrum by the EN 1998-1 "
                             "eq. (3.6) factor {:.4f}",
                             100.0 * damping, 100.0 * near.damping, d.factor);
    } else {
        const auto& below = *(above - 1);
        d.lo = below;
        d.hi = *above;
        d.weight_hi = std::log(damping / below.damping) / std::log(above->damping / below.damping);
        d.note = fmt::format("{:.4g}% damping interpolated on log axes between {:.4g}% and {:.4g}%",
                             100.0 * damping, 100.0 * below.damping, 100.0 * above->damping);
    }
    return d;
}

double DampedSpectra::zpa_g() const {
    if (generator_) return checked(generator_(0.05)).psa_g.back();
    return set_.front().psa_g.back();
}

double DampedSpectra::zpa_frequency_hz() const {
    if (generator_) return checked(generator_(0.05)).frequency_hz.back();
    return set_.front().frequency_hz.back();
}

std::string DampedSpectra::label() const { return label_; }

}  // namespace freestand::rocking
