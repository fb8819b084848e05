#include "validate/thesis.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace freestand::validate {

namespace {

Fact num(std::string key, double v, std::string unit, std::string text, std::string where,
         int line, std::string quote) {
    return Fact{std::move(key), v, std::move(unit), std::move(text),
                Citation{std::move(where), line, std::move(quote)}};
}

Fact obs(std::string key, std::string text, std::string where, int line, std::string quote) {
    return Fact{std::move(key), std::nullopt, "", std::move(text),
                Citation{std::move(where), line, std::move(quote)}};
}

}  // namespace

const std::vector<Fact>& facts() {
    static const std::vector<Fact> list{
        // Chapter 3: rigid steel specimens TS1-TS3 on a steel plate, uniaxial table.
        num("ts.stroke_m", 0.075, "m", "shake-table displacement range +-0.075 m",
            "s.3.3.2, Table 3-1", 826, "0.075"),
        num("ts1.alpha_rad", 0.245, "rad", "TS1 critical angle", "s.3.3.3.1, Table 3-2", 865,
            "0.245"),
        num("ts1.R_m", 0.62, "m", "TS1 diagonal length R", "s.3.3.3.1, Table 3-2", 865, "0.62"),
        num("ts2.alpha_rad", 0.322, "rad", "TS2 critical angle", "s.3.3.3.1, Table 3-2", 870,
            "0.322"),
        num("ts2.R_m", 0.47, "m", "TS2 diagonal length R", "s.3.3.3.1, Table 3-2", 870, "0.47"),
        num("ts3.alpha_rad", 0.463, "rad", "TS3 critical angle", "s.3.3.3.1, Table 3-2", 873,
            "0.463"),
        num("ts3.R_m", 0.34, "m", "TS3 diagonal length R", "s.3.3.3.1, Table 3-2", 873, "0.34"),
        num("ts1.p_radps", 3.34, "rad/s", "TS1 frequency parameter p (column headed Hz; the values are rad/s)",
            "s.3.3.3.1, Table 3-2", 865, "3.34"),
        num("ts1.mass_kg", 38.0, "kg", "TS1 mass", "s.3.3.3.1, Table 3-2", 865, "38"),
        num("ts2.p_radps", 3.77, "rad/s", "TS2 frequency parameter p", "s.3.3.3.1, Table 3-2",
            870, "3.77"),
        num("ts2.mass_kg", 38.0, "kg", "TS2 mass", "s.3.3.3.1, Table 3-2", 870, "38"),
        num("ts3.p_radps", 4.42, "rad/s", "TS3 frequency parameter p", "s.3.3.3.1, Table 3-2",
            873, "4.42"),
        num("ts3.mass_kg", 35.0, "kg", "TS3 mass", "s.3.3.3.1, Table 3-2", 873, "35"),
        num("steel.mu_s", 0.72, "", "static friction of the specimens on steel", "s.3.3.3.2",
            881, "0.15, 0.32, 0.48 and 0.72"),
        num("steel.restitution", 0.98, "", "restitution on steel (average)",
            "s.3.3.3.3, Table 3-3", 896, "0.98"),
        obs("ts.restitution_slenderness",
            "restitution decreased (dissipation increased) as slenderness decreased, TS1 to TS3",
            "s.3.3.4.3", 1039,
            "decrease in coefficient of restitution or increase of energy dissipation with a "
            "decrease of slenderness"),
        num("ts.sine_g", 0.8, "g", "sine tests at 0.8 g, 0.5-10 Hz, mu 0.72",
            "s.3.3.4.1, Table 3-5", 972, "0.5,1,2,3,4,5,6,7,8,9,10"),
        num("ts.duration_s", 5.0, "s",
            "the harmonic sliding tests, run 'similar to the case of pure rocking', lasted 5 s",
            "s.3.3.5.1", 1104, "for a duration of 5secs"),
        obs("ts.overturn_below_2hz", "TS1, TS2 and TS3 overturned below 2 Hz",
            "s.3.3.4.1 (text of Fig. 3-13)", 988, "overturned for frequencies lesser than 2Hz"),
        obs("ts.overturn_2hz", "at 2 Hz TS1 and TS2 overturned, TS3 kept rocking",
            "s.3.3.4.1 (text of Fig. 3-13)", 988,
            "at 2Hz, TS1 and TS2 overturned while TS3 remained in the rocking phase of motion"),
        obs("ts.higher_frequencies",
            "above the overturning frequencies the peak rocking angles are plotted (Fig. 3-13, "
            "lost) and decrease with frequency",
            "s.3.3.4.1", 1003,
            "slenderness has an insignificant effect on peak rocking angles at higher frequencies"),
        obs("ts.virtual_zero", "higher frequencies diminished rocking to a virtual zero",
            "s.3.3.4.1", 1007,
            "higher frequencies diminished rocking motion to a virtual zero value"),
        obs("ts.ishiyama_eq", "Ishiyama's bound V = 0.4 sqrt(8 g R (1 - cos a) / (3 cos a))",
            "s.3.3.4.1, Eq. 3.41", 990, "V peak = 0.4"),
        num("ts1.vpeak_mps", 0.283, "m/s", "TS1 velocity bound", "s.3.3.4.1, Table 3-6", 997,
            "0.283"),
        num("ts2.vpeak_mps", 0.326, "m/s", "TS2 velocity bound", "s.3.3.4.1, Table 3-6", 998,
            "0.326"),
        num("ts3.vpeak_mps", 0.499, "m/s", "TS3 velocity bound", "s.3.3.4.1, Table 3-6", 999,
            "0.499"),
        num("ts1.v_0.5hz_mps", 1.75, "m/s", "table velocity, TS1 run at 0.5 Hz",
            "s.3.3.4.1, Table 3-6", 997, "1.75"),
        num("ts1.v_1hz_mps", 0.875, "m/s", "table velocity, TS1 run at 1 Hz",
            "s.3.3.4.1, Table 3-6", 997, "0.875"),
        num("ts1.v_2hz_mps", 0.436, "m/s", "table velocity, TS1 run at 2 Hz",
            "s.3.3.4.1, Table 3-6", 997, "0.436"),
        num("ts2.v_0.5hz_mps", 1.765, "m/s", "table velocity, TS2 run at 0.5 Hz",
            "s.3.3.4.1, Table 3-6", 998, "1.765"),
        num("ts2.v_1hz_mps", 0.884, "m/s", "table velocity, TS2 run at 1 Hz",
            "s.3.3.4.1, Table 3-6", 998, "0.884"),
        num("ts2.v_2hz_mps", 0.421, "m/s", "table velocity, TS2 run at 2 Hz",
            "s.3.3.4.1, Table 3-6", 998, "0.421"),
        num("ts3.v_0.5hz_mps", 1.77, "m/s", "table velocity, TS3 run at 0.5 Hz",
            "s.3.3.4.1, Table 3-6", 999, "1.77"),
        num("ts3.v_1hz_mps", 0.88, "m/s", "table velocity, TS3 run at 1 Hz",
            "s.3.3.4.1, Table 3-6", 999, "0.88"),
        num("ts3.v_2hz_mps", 0.431, "m/s", "table velocity, TS3 run at 2 Hz",
            "s.3.3.4.1, Table 3-6", 999, "0.431"),
        obs("ts.velocity_integrated",
            "the table velocities of Table 3-6 were integrated from the recorded acceleration",
            "s.3.3.4.1", 993, "calculated by the numerical integration of recorded acceleration"),
        obs("ts.stroke_limit", "sines limited to |X_g / omega^2| <= 0.075 m by the stroke",
            "s.3.3.4.4, Eq. 3.42", 1055, "can generate a maximum displacement of"),
        num("ts.lateral_g", 0.6, "g", "lateral (out-of-plane) acceleration at 2 Hz",
            "s.3.3.4.2", 1027, "was 0.6g"),
        obs("ts.uniaxial", "the specimens' table is uniaxial (horizontal motion only)", "s.3.3.2",
            820, "A uni-axial hydraulic shake table"),
        // Table 3-4: sines below the static uplift threshold X_s = g tan(alpha), 11 frequencies.
        obs("ts.rest_frequencies", "the rest tests swept sines of 0.5 and 1-10 Hz (11 per run)",
            "s.3.3.4.1", 944,
            "sinusoidal waves of different frequencies varying from 0.5Hz to 10 Hz"),
        num("ts1.rest_run1_g", 0.25, "g", "Table 3-4 run 1: TS1, X_s 0.25 g, sines at 0.25 g",
            "s.3.3.4.1, Table 3-4", 954, "0.25"),
        num("ts1.rest_run2_g", 0.2, "g", "Table 3-4 run 2: TS1, X_s 0.25 g, sines at 0.2 g",
            "s.3.3.4.1, Table 3-4", 955, "0.2"),
        num("ts2.rest_run3_g", 0.33, "g", "Table 3-4 run 3: TS2, X_s 0.33 g, sines at 0.33 g",
            "s.3.3.4.1, Table 3-4", 956, "0.33"),
        num("ts2.rest_run4_g", 0.3, "g", "Table 3-4 run 4: TS2, X_s 0.33 g, sines at 0.3 g",
            "s.3.3.4.1, Table 3-4", 957, "0.3"),
        num("ts3.rest_run5_g", 0.5, "g", "Table 3-4 run 5: TS3, X_s 0.5 g, sines at 0.5 g",
            "s.3.3.4.1, Table 3-4", 958, "0.5"),
        num("ts3.rest_run6_g", 0.45, "g", "Table 3-4 run 6: TS3, X_s 0.5 g, sines at 0.45 g",
            "s.3.3.4.1, Table 3-4", 959, "0.45"),
        obs("ts.rest_all", "every run of Table 3-4 stayed at rest: no rocking initiation",
            "s.3.3.4.1", 946,
            "All the test runs corresponding to Table.3-4 resulted in no rocking initiation"),
        // The random (seismic) table test of s.3.3.4, before the sines.
        num("ts.random_g", 0.8, "g",
            "random test: a synthetic history of the site's design spectrum (Fig. 2-3, lost) at "
            "0.8 g PGA",
            "s.3.3.4", 905, "synthetic time history corresponding to 0.8g PGA value"),
        obs("ts.random_scaled", "the 0.8 g history was the 0.3 g one scaled up", "s.3.3.4", 905,
            "synthetic time history at 0.3g was suitably scaled up"),
        obs("ts.random_outcome", "random test at 0.8 g: TS1 and TS2 overturned, TS3 stood",
            "s.3.3.4", 919,
            "Test specimens TS1 and TS2 overturned due to base excitation as shown in Fig.3 "
            "However, TS3 could sustain the effect of ground shaking"),

        // Chapters 2 and 5: the single glove box on a PVC sheet (full-scale tri-axial tests).
        obs("gb.test_levels", "tests from 0.1 g to 0.4 g in steps of 0.1 g, vertical 2/3",
            "s.2.4.1.1", 362, "varied from 0.1g to 0.4 g in steps of 0.1g"),
        num("gb.onset_g", 0.15, "g",
            "the glove box started moving at 0.15 g; friction taken as 0.15 from this",
            "s.2.4.1.1", 368, "started moving after overcoming sliding friction at 0.15g"),
        obs("gb.table_band", "table signals band-pass filtered 0.5-50 Hz", "s.2.4.1.1", 368,
            "band pass filter with a range of 0.5 to 50 Hz"),
        num("gb.alpha_rad", 0.41, "rad", "glove box critical angle", "s.5.2.1, Table 5-2", 1914,
            "0.41"),
        obs("gb.slides_0.1_to_0.2", "in the tests it started sliding between 0.1 g and 0.2 g",
            "s.5.3.3", 1967,
            "started sliding when the base acceleration changed from 0.1g to 0.2g"),
        obs("gb.fe_rest_0.1", "at 0.1 g at rest; 5 Hz response peak put down to "
                              "frequency-induced rocking (FE analysis)",
            "s.5.4 (d)", 2064, "at 0.1g PGA value, glove box was in rest state"),
        obs("gb.test_rest_0.1", "negligible sliding at 0.1 g in the tests", "s.5.5", 2162,
            "negligible sliding displacement was observed in test"),
        num("gb.mu", 0.15, "", "friction of the worked example", "s.5.5, Eq. 5.1", 2166,
            "0.15(1-0.4*2.2/9.81)"),
        num("gb.av_mps2", 2.2, "m/s^2", "A_v of the worked example (site 10% spectrum)",
            "s.5.5, Eq. 5.1", 2166, "0.15(1-0.4*2.2/9.81)"),
        num("gb.fes_hz", 1.2, "Hz", "f_es read off the site's 10% spectrum", "s.5.5", 2172,
            "fe_s = 1.2Hz"),
        num("gb.delta_d_mm", 40.0, "mm", "DeltaD, the table's peak displacement (test data)",
            "s.5.5", 2174, "was 40mm"),
        num("gb.energy_0.2g_mm", 56.0, "mm", "energy method, single box, 0.2 g", "s.5.5", 2182,
            "56 mm"),
        num("gb.energy_0.3g_mm", 102.0, "mm", "energy method, single box, 0.3 g", "s.5.5", 2186,
            "102mm"),
        num("gb.asce_0.1g_mm", 4.0, "mm", "ASCE 4, single box, 0.1 g", "s.5.5", 2192, "4mm"),
        num("gb.asce_0.2g_mm", 47.0, "mm", "ASCE 4, single box, 0.2 g", "s.5.5", 2196, "47 mm"),
        num("gb.asce_0.3g_mm", 124.0, "mm", "ASCE 4, single box, 0.3 g", "s.5.5", 2200, "124mm"),
        obs("gb.final_displacements", "measured final displacements only in Fig. 5-20 (lost)",
            "s.5.6, Fig. 5-20", 2232, "Comparison of final displacements obtained from test"),
        obs("gb.pvc_slide_rock", "on PVC (mu 0.15) sliding cum rocking above 0.15 g",
            "s.5.7", 2244,
            "Sliding cum rocking motion initiates when amplitude of base excitation crosses 0.15g"),
        num("gb.steel_rest_g", 0.3, "g",
            "on steel pads (mu 0.72) at rest up to 0.3 g (FE-based diagram Fig. 5-22, which the "
            "text calls Fig. 5-27)",
            "s.5.7", 2246, "remain in rest state till amplitude of base excitation is below 0.3g"),
        obs("gb.steel_rock_0.3_0.4", "on steel pads frequency-induced rocking at 0.3-0.4 g",
            "s.5.7", 2246,
            "between 0.3g -0.4g, glove box will initiate frequency induced rocking"),
        obs("gb.mode", "predominantly sliding, with very low amplitude rocking", "s.5.8", 2256,
            "predominant mode of motion was sliding however very low amplitude rocking"),

        // Chapters 6 and 7: two glove boxes joined by a tunnel, then braced.
        num("pair.mu", 0.15, "", "friction of the pair's worked example", "s.6.4", 2424,
            "0.15(1 \\text{-} 0.4"),
        num("pair.av_mps2", 2.1, "m/s^2", "A_v of the pair's worked example", "s.6.4", 2424,
            "2.1 \\text{/} 9.81"),
        num("pair.fes_hz", 1.1, "Hz", "f_es of the pair (site 10% spectrum)", "s.6.4", 2434,
            "it was 1.1Hz"),
        num("pair.delta_d_mm", 40.0, "mm", "DeltaD of the pair at 0.2 g", "s.6.4", 2434,
            "as 40mm"),
        num("pair.mass_kg", 1093.0, "kg", "mass of the two boxes", "s.6.4", 2434, "1093Kg"),
        obs("pair.no_slide_0.1g", "at 0.1 g the pair had not started sliding (no energy "
            "estimate)", "s.6.4", 2420, "since sliding had not started for that pba value"),
        num("pair.energy_0.2g_mm", 58.0, "mm", "energy method, pair, 0.2 g", "s.6.4", 2446,
            "0.058m"),
        num("pair.energy_0.3g_mm", 91.0, "mm", "energy method, pair, 0.3 g", "s.6.4", 2450,
            "0.091"),
        num("pair.energy_0.4g_mm", 134.0, "mm", "energy method, pair, 0.4 g", "s.6.4", 2454,
            "0.134"),
        num("pair.asce_0.1g_mm", 4.0, "mm", "ASCE 4, pair, 0.1 g", "s.6.4", 2460, "0.004"),
        num("pair.asce_0.2g_mm", 56.0, "mm", "ASCE 4, pair, 0.2 g", "s.6.4", 2464, "0.056m"),
        num("pair.asce_0.3g_mm", 105.0, "mm", "ASCE 4, pair, 0.3 g", "s.6.4", 2468, "0.105"),
        num("pair.asce_0.4g_mm", 165.0, "mm", "ASCE 4, pair, 0.4 g", "s.6.4", 2472, "0.165"),
        obs("braced.method", "braced pair: same method as Chapter 5", "s.7.4", 2604,
            "Methodology for obtaining equivalent sliding displacement is same"),
        num("braced.energy_0.2g_mm", 57.0, "mm", "energy method, braced pair, 0.2 g", "s.7.4",
            2609, "57 mm"),
        num("braced.energy_0.3g_mm", 91.0, "mm", "energy method, braced pair, 0.3 g", "s.7.4",
            2612, "91 mm"),
        num("braced.energy_0.4g_mm", 134.0, "mm", "energy method, braced pair, 0.4 g", "s.7.4",
            2616, "134 mm"),
        num("braced.asce_0.1g_mm", 4.0, "mm", "ASCE 4, braced pair, 0.1 g", "s.7.4", 2622,
            "4mm"),
        num("braced.asce_0.2g_mm", 56.0, "mm", "ASCE 4, braced pair, 0.2 g", "s.7.4", 2626,
            "56 mm"),
        num("braced.asce_0.3g_mm", 105.0, "mm", "ASCE 4, braced pair, 0.3 g", "s.7.4", 2630,
            "105 mm"),
        num("braced.asce_0.4g_mm", 165.0, "mm", "ASCE 4, braced pair, 0.4 g", "s.7.4", 2634,
            "165 mm"),
        obs("braced.integrity", "the braced pair kept its integrity up to 0.4 g", "s.7.3", 2578,
            "Interconnected GBs maintained integrity up to 0.4g PGA value"),
        num("unbraced.box_kg", 370.0, "kg", "each glove box of the unbraced pair", "s.2.4.2", 398,
            "370 Kg each"),
        num("unbraced.lead_kg", 96.0, "kg", "eccentric lead shielding in one box", "s.2.4.2", 429,
            "eccentric mass of 96 kg"),
        num("unbraced.central_kg", 250.0, "kg", "central mass in the other box", "s.2.4.2", 429,
            "250 Kg fixed central mass"),
        num("unbraced.relative_0.2g_mm", 7.0, "mm", "relative sliding up to 0.2 g, tunnel seated",
            "s.6.3", 2385, "limited to 0.007m"),
        obs("unbraced.tilt_0.3g", "at 0.3 g the tunnel tilted", "s.6.3", 2385,
            "at 0.3g pba value, material transfer tunnel tilted"),
        num("unbraced.relative_0.4g_mm", 25.0, "mm", "relative displacement at 0.4 g, tunnel "
            "slipped off its O-rings", "s.6.3", 2385, "relative displacement increased to 0.025m"),
    };
    return list;
}

const Fact& fact(const std::string& key) {
    for (const Fact& f : facts()) {
        if (f.key == key) return f;
    }
    throw std::logic_error("validate: no thesis fact '" + key + "'");
}

double value(const std::string& key) {
    const Fact& f = fact(key);
    if (!f.value) throw std::logic_error("validate: thesis fact '" + key + "' has no value");
    return *f.value;
}

std::string cite_text(const Citation& c) {
    return fmt::format("thesis {}, line {}", c.where, c.line);
}

}  // namespace freestand::validate
