#include "report/references.hpp"

#include <algorithm>
#include <stdexcept>

namespace freestand::report {

const std::vector<Reference>& references() {
    static const std::vector<Reference> list{
        {"docs/methods.md",
         "freestand methods: the equations, sources, conventions, decision policy and limits "
         "of every model, docs/methods.md in the freestand repository (cited as "
         "docs/methods.md s.N)."},
        {"ASCE 4-16",
         "ASCE/SEI 4-16, Seismic Analysis of Safety-Related Nuclear Structures, American "
         "Society of Civil Engineers, 2017 (sliding of unanchored bodies)."},
        {"ASCE 43-05",
         "ASCE/SEI 43-05, Seismic Design Criteria for Structures, Systems, and Components in "
         "Nuclear Facilities, Appendix A, American Society of Civil Engineers, 2005."},
        {"SRP 3.7.1",
         "US NRC, Standard Review Plan, NUREG-0800, Section 3.7.1 Seismic Design Parameters, "
         "Rev. 4, 2014 (Option 1 Approach 2 acceptance of time histories)."},
        {"RG 1.60",
         "US NRC, Regulatory Guide 1.60, Design Response Spectra for Seismic Design of Nuclear "
         "Power Plants, Rev. 2, 2014."},
        {"NUREG/CR-6728",
         "McGuire, R.K., Silva, W.J., Costantino, C.J., Technical Basis for Revision of "
         "Regulatory Guidance on Design Ground Motions, NUREG/CR-6728, US NRC, 2001."},
        {"Housner 1963",
         "Housner, G.W., The behavior of inverted pendulum structures during earthquakes, "
         "Bulletin of the Seismological Society of America 53(2), 403-417, 1963."},
        {"Shenton 1996",
         "Shenton, H.W., Criteria for initiation of slide, rock, and slide-rock rigid-body "
         "modes, Journal of Engineering Mechanics 122(7), 690-693, 1996."},
        {"Ishiyama 1982",
         "Ishiyama, Y., Motions of rigid bodies and criteria for overturning by earthquake "
         "excitations, Earthquake Engineering and Structural Dynamics 10(5), 635-650, 1982."},
        {"Makris & Konstantinidis 2003",
         "Makris, N., Konstantinidis, D., The rocking spectrum and the limitations of "
         "practical design methodologies, Earthquake Engineering and Structural Dynamics "
         "32(2), 265-289, 2003."},
        {"Al Atik & Abrahamson 2010",
         "Al Atik, L., Abrahamson, N., An improved method for nonstationary spectral matching, "
         "Earthquake Spectra 26(3), 601-617, 2010."},
        {"Nigam & Jennings 1969",
         "Nigam, N.C., Jennings, P.C., Calculation of response spectra from strong-motion "
         "earthquake records, Bulletin of the Seismological Society of America 59(2), "
         "909-922, 1969."},
        {"Boore & Bommer 2005",
         "Boore, D.M., Bommer, J.J., Processing of strong-motion accelerograms: needs, options "
         "and consequences, Soil Dynamics and Earthquake Engineering 25(2), 93-115, 2005."},
        {"Clopper & Pearson 1934",
         "Clopper, C.J., Pearson, E.S., The use of confidence or fiducial limits illustrated in "
         "the case of the binomial, Biometrika 26(4), 404-413, 1934."},
        {"Baker 2015",
         "Baker, J.W., Efficient analytical fragility function fitting using dynamic structural "
         "analysis, Earthquake Spectra 31(1), 579-599, 2015 (lognormal fragility by maximum "
         "likelihood)."},
        {"FEMA P-58",
         "FEMA P-58-1, Seismic Performance Assessment of Buildings, Volume 1 - Methodology, "
         "Federal Emergency Management Agency, 2012 (fragility functions)."},
        {"Saraswat 2017",
         "Saraswat, A., Response Evaluation of Freestanding Systems subjected to Seismic "
         "Loading, PhD thesis, Homi Bhabha National Institute / Bhabha Atomic Research Centre, "
         "2017 (shake-table tests of rigid blocks and glove boxes; the ASCE 4 and energy "
         "worked examples)."},
    };
    return list;
}

std::vector<Reference> references(const std::vector<std::string>& keys) {
    const std::vector<Reference>& all = references();
    std::vector<Reference> out;
    for (const std::string& key : keys) {
        const auto it = std::find_if(all.begin(), all.end(),
                                     [&](const Reference& r) { return r.key == key; });
        if (it == all.end()) throw std::out_of_range("unknown reference key \"" + key + "\"");
        out.push_back(*it);
    }
    return out;
}

}  // namespace freestand::report
