// Speed against error of fragility analysis (docs/methods.md s.9). Four parts:
//  1. Throughput: 5,000 samples (two simulations each, x and y: 10,000 block simulations of
//     20 s generated histories) of the glove box on PVC, block-ts3 and block-ts1 at levels where
//     they rest, slide, rock and overturn, on 1 and 2 threads; wall time, simulations/s/core,
//     the mix of modes. Overturned runs stop early, so the mix is printed beside the speed.
//  2. The reference run: block-ts1, 10 levels x 100 samples with its generated histories, on 2
//     threads, split into history generation, simulations and aggregation + rendering.
//  3. Error against an exact answer: a pure-sliding block under a 2 Hz sine with friction
//     uniform on [0.1, 0.2]; P(slide > 30 mm) = P(mu < mu*) from Newmark's closed-form slip
//     (tests/support/sliding_sine.hpp); |p - exact| and the 95% interval width against N.
//  4. How the interval narrows with N on block-ts3 near its median (the first N samples of a
//     400-sample level: the samples are independent draws, so a prefix is a smaller run).
//  5. The 3D body's throughput: block-ts3's samples at levels where it rocks, with the case's
//     models (a sample that rocks runs the 3D body, one that only slides biaxial sliding), on
//     2 threads; the aim is 200 simulations per second or more.
// Wall times on a shared virtual machine drift by up to 2x between minutes; read the ratios.
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <thread>
#include <unistd.h>
#include <vector>

#include "assess/case.hpp"
#include "core/statistics.hpp"
#include "fragility/fragility.hpp"
#include "report/fragility_report.hpp"
#include "support/sliding_sine.hpp"
#include "timing.hpp"

using namespace freestand;
namespace fs = std::filesystem;

namespace {

using bench::Clock;
using bench::seconds_since;
using bench::source_dir;
// CPU time of the whole process (all threads): on a loaded machine, simulations per CPU
// second is the per-core rate a quiet machine would give.
double cpu_s() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

std::vector<std::size_t> all_indices(const fragility::Runner& r) {
    std::vector<std::size_t> all(r.total());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
    return all;
}


struct Mix {
    int rest = 0, slide_only = 0, rocked = 0, overturned = 0;
    void add(const fragility::SampleResult& x) {
        if (x.overturned)
            ++overturned;
        else if (x.rock_max_over_alpha > 0.0)
            ++rocked;
        else if (x.slide_max_m > 0.0)
            ++slide_only;
        else
            ++rest;
    }
};

// Part 1: three scenes whose samples rest, slide (the glove box on PVC), rock without
// overturning and overturn (the steel blocks), 10,000 simulations in all.
void throughput() {
    struct Scene {
        const char* case_name;
        std::vector<double> pga_g;
        int samples;
    };
    const std::vector<Scene> scenes{{"glovebox-single", {0.1, 0.2, 0.3, 0.4, 0.5}, 400},
                                    {"block-ts3", {0.2, 0.3, 0.4, 0.5, 0.6}, 400},
                                    {"block-ts1", {0.1, 0.15, 0.2, 0.25}, 250}};
    std::printf("1. throughput: 10,000 simulations of 20 s generated histories (2 per sample, "
                "x and y), pools of 20 sets\n");
    std::printf("   %-16s %7s %9s %9s %7s %6s %6s %6s %6s\n", "case", "sims", "1 thr s",
                "2 thr s", "pool s", "rest", "slide", "rock", "over");
    double total_1 = 0.0, total_2 = 0.0, sims = 0.0, cpu_total = 0.0;
    Mix all;
    for (const Scene& sc : scenes) {
        const assess::Case c =
            assess::read_case(source_dir() / "cases" / (std::string(sc.case_name) + ".toml"));
        fragility::Config cfg;
        cfg.pga_g = sc.pga_g;
        cfg.samples = sc.samples;
        fragility::Runner runner(c, cfg);
        const auto t_pool = Clock::now();
        runner.prepare(assess::RunSettings(2));
        const double pool_s = seconds_since(t_pool);
        const auto indices = all_indices(runner);
        double s[2] = {0.0, 0.0};
        std::vector<fragility::SampleResult> out;
        for (int threads : {1, 2}) {
            const auto t0 = Clock::now();
            const double c0 = cpu_s();
            out = fragility::run_samples(runner, indices, threads);
            s[threads - 1] = seconds_since(t0);
            cpu_total += cpu_s() - c0;
        }
        Mix m;
        for (const auto& x : out) m.add(x), all.add(x);
        const double n = 2.0 * static_cast<double>(indices.size());
        std::printf("   %-16s %7.0f %9.2f %9.2f %7.2f %6d %6d %6d %6d\n", sc.case_name, n, s[0],
                    s[1], pool_s, m.rest, m.slide_only, m.rocked, m.overturned);
        total_1 += s[0];
        total_2 += s[1];
        sims += n;
    }
    std::printf("   all: %.0f simulations in %.2f s on 1 thread (%.0f /s), %.2f s on 2 threads "
                "(%.0f /s, %.0f /s/core); %.0f simulations per CPU second; samples: %d at rest, "
                "%d slid only, %d rocked without overturning, %d overturned\n\n",
                sims, total_1, sims / total_1, total_2, sims / total_2, sims / total_2 / 2.0,
                2.0 * sims / cpu_total, all.rest, all.slide_only, all.rocked, all.overturned);
}

void issue_run(const assess::Case& c) {
    std::printf("2. block-ts1, 10 levels x 100 samples, generated histories, 2 threads\n");
    fragility::Config cfg;
    for (int i = 1; i <= 10; ++i) cfg.pga_g.push_back(0.1 * i);
    cfg.samples = 100;
    const auto t0 = Clock::now();
    const double c0 = cpu_s();
    fragility::Runner runner(c, cfg);
    runner.prepare(assess::RunSettings(2));
    const double t_pool = seconds_since(t0);
    const double c1 = cpu_s();
    const auto t1 = Clock::now();
    auto samples = fragility::run_samples(runner, all_indices(runner), 2);
    const double t_sims = seconds_since(t1);
    const double c2 = cpu_s();
    const auto t2 = Clock::now();
    const fragility::Result r = fragility::aggregate(fragility::make_meta(c, cfg), std::move(samples));
    const report::RenderedFragility out = report::render_fragility(r, report::Stamp{});
    const double t_out = seconds_since(t2);
    const double total = seconds_since(t0);
    std::printf("   total %.2f s: histories %.2f s (%.0f%%), 2,000 simulations %.2f s (%.0f%%), "
                "aggregate + fit + render %.3f s (%zu bytes of report.html)\n",
                total, t_pool, 100.0 * t_pool / total, t_sims, 100.0 * t_sims / total, t_out,
                out.html.size());
    std::printf("   CPU: histories %.2f s, simulations %.2f s (a quiet 2-core machine: about "
                "%.1f s wall)\n",
                c1 - c0, c2 - c1, (c2 - c0) / 2.0 + t_out);
    for (std::size_t e = 0; e < fragility::all_events.size(); ++e) {
        const auto& f = r.fits[e];
        if (f.fit)
            std::printf("   %-8s theta_m %.3f g, beta %.3f\n",
                        fragility::event_name(fragility::all_events[e]), f.fit->theta_m_g,
                        f.fit->beta);
        else
            std::printf("   %-8s no fit: %s\n", fragility::event_name(fragility::all_events[e]),
                        f.note.c_str());
    }
    std::printf("\n");
}

void exact_sliding() {
    std::printf("3. error against the exact probability: pure sliding under 0.3 g, 2 Hz for 5 s, "
                "mu uniform [0.1, 0.2], allowable 30 mm\n");
    const fs::path dir = fs::temp_directory_path() / ("bench_fragility_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string record = (dir / "sine.csv").string();
    {
        std::ofstream out(record);
        out << "time_s,accel_g\n";
        for (int i = 0; i <= 5000; ++i)
            out << i * 0.001 << "," << std::sin(2.0 * M_PI * 2.0 * i * 0.001) << "\n";
    }
    std::ofstream(dir / "slider.toml")
        << "[component]\nname = \"slider\"\nmass_kg = 100.0\nwidth_m = 4.0\ndepth_m = 4.0\n"
           "height_m = 0.2\nmu_s = 0.15\nrestitution = 0.5\nallowable_slide_m = 0.03\n"
           "[site]\npga_g = [0.3]\n[uncertainty]\nmu_s = { dist = \"uniform\", lo = 0.1, hi = 0.2 }\n";
    const assess::Case c = assess::read_case(dir / "slider.toml");
    const double mu_star = test::critical_mu(0.3, 2.0, 5.0, 0.03);
    const double exact = (mu_star - 0.1) / 0.1;
    std::printf("   mu* = %.5f, exact P = %.4f\n", mu_star, exact);
    std::printf("   %6s %8s %10s %12s %14s %10s\n", "N", "p", "|p-exact|", "95% width",
                "binomial sd", "time s");
    for (int n : {100, 400, 1600, 6400}) {
        fragility::Config cfg;
        cfg.pga_g = {0.3};
        cfg.samples = n;
        cfg.seed = 3;
        cfg.record_files = {record};
        fragility::Runner runner(c, cfg);
        runner.prepare(assess::RunSettings(2));
        const auto t0 = Clock::now();
        const fragility::Result r = fragility::aggregate(
            fragility::make_meta(c, cfg), fragility::run_samples(runner, all_indices(runner), 2));
        const double s = seconds_since(t0);
        const fragility::Count& k = r.levels[0].events[1];
        std::printf("   %6d %8.4f %10.4f %12.4f %14.4f %10.2f\n", n, k.p, std::abs(k.p - exact),
                    k.ci[1] - k.ci[0], std::sqrt(exact * (1.0 - exact) / n), s);
    }
    fs::remove_all(dir);
    std::printf("\n");
}

void interval_width() {
    std::printf("4. interval width against N: block-ts3 overturning at 0.5 and 0.6 g, prefixes "
                "of 400 samples\n");
    const assess::Case c = assess::read_case(source_dir() / "cases" / "block-ts3.toml");
    fragility::Config cfg;
    cfg.pga_g = {0.5, 0.6};
    cfg.samples = 400;
    fragility::Runner runner(c, cfg);
    runner.prepare(assess::RunSettings(2));
    const auto samples = fragility::run_samples(runner, all_indices(runner), 2);
    std::printf("   %6s %26s %26s\n", "N", "0.5 g k/n [95%] width", "0.6 g k/n [95%] width");
    for (int n : {25, 50, 100, 200, 400}) {
        std::printf("   %6d", n);
        for (int level = 0; level < 2; ++level) {
            int k = 0;
            for (int i = 0; i < n; ++i)
                k += samples[static_cast<std::size_t>(level * 400 + i)].overturned;
            const auto ci = core::clopper_pearson(k, n, 0.95);
            std::printf("  %3d/%-3d [%.3f, %.3f] %.3f", k, n, ci[0], ci[1], ci[1] - ci[0]);
        }
        std::printf("\n");
    }
}

void body3d_throughput() {
    std::printf("\n5. the 3D body in fragility: block-ts3 at 0.5, 0.6 and 0.7 g, 200 samples each, "
                "the case's models (the 3D body for a sample that rocks), 2 threads\n");
    const assess::Case c = assess::read_case(source_dir() / "cases" / "block-ts3.toml");
    fragility::Config cfg;
    cfg.pga_g = {0.5, 0.6, 0.7};
    cfg.samples = 200;
    cfg.models.biaxial_slide = true;
    cfg.models.body3d = true;
    fragility::Runner runner(c, cfg);
    runner.prepare(assess::RunSettings(2));
    const auto indices = all_indices(runner);
    const auto t0 = Clock::now();
    const double c0 = cpu_s();
    const auto out = fragility::run_samples(runner, indices, 2);
    const double wall_s = seconds_since(t0), cpu = cpu_s() - c0;
    Mix m;
    for (const auto& x : out) m.add(x);
    const double whole = static_cast<double>(m.rocked + m.overturned);
    std::printf("   %zu samples in %.2f s wall (%.0f /s; %.0f per CPU second x 2 cores): %d at "
                "rest, %d slid only (biaxial), %.0f ran the 3D body (%d overturned): at least "
                "%.0f 3D simulations per second\n\n",
                indices.size(), wall_s, static_cast<double>(indices.size()) / wall_s,
                2.0 * static_cast<double>(indices.size()) / cpu, m.rest, m.slide_only, whole,
                m.overturned, whole / wall_s);
}

}  // namespace

int main() {
    const assess::Case ts1 = assess::read_case(source_dir() / "cases" / "block-ts1.toml");
    std::printf("bench_fragility (hardware threads: %u)\n\n", std::thread::hardware_concurrency());
    throughput();
    issue_run(ts1);
    exact_sliding();
    interval_width();
    body3d_throughput();
    return 0;
}
