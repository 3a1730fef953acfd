/// @file narrowphase_bench.cpp
/// @brief The side by side of lecture 11: the same shape pairs through each narrowphase algorithm.
///
/// Each *pair set* is a list of shape pairs with random orientations (fixed
/// seed): boxes overlapping by 1 mm to 5 cm ("touching"), boxes 5 mm to 5 cm
/// apart ("separated": within and beyond the speculative reach of 1 cm), and
/// capsule, cylinder and hull pairs touching. Each algorithm runs over the
/// whole set `repeats` times; a row gives the median over the repeats of the
/// time per pair, the contacts found, and the mean and largest iteration
/// counts of GJK, EPA and MPR (support queries, ConvexIterations).
#include "narrowphase_bench.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>

#include "collision/convex_pairs.hpp"
#include "collision/epa.hpp"
#include "collision/gjk.hpp"

namespace stepwise::bench {

const char* const kNarrowphaseUsage =
    "usage: stepwise-bench narrowphase [--quick] [--pairs N] [--repeats N] [--seed S]\n"
    "\n"
    "  The same shape pairs (boxes touching and apart, capsules, cylinders, hulls; random\n"
    "  orientations, fixed seed) through SAT, GJK+EPA and MPR: median ns per pair and the\n"
    "  mean and largest iteration counts of GJK, EPA and MPR.\n"
    "\n"
    "  --quick       200 pairs, 3 repeats (the CTest test bench_narrowphase_quick)\n"
    "  --pairs N     pairs per set (default 2000)\n"
    "  --repeats N   timed passes over each set; the median is printed (default 11)\n"
    "  --seed S      random seed (default 1)\n"
    "\n";

namespace {

struct Options {
    int pairs = 2000;
    int repeats = 11;
    unsigned seed = 1;
};

using Pair = std::pair<Geometry, Geometry>;

/// A cube of half edge @p h as a hull, written out (the scene loader's builder is not needed here).
std::shared_ptr<ConvexHull> cubeHull(Real h) {
    auto hull = std::make_shared<ConvexHull>();
    for (int k = 0; k < 8; ++k) hull->vertices.emplace_back((k & 1) ? h : -h, (k & 2) ? h : -h, (k & 4) ? h : -h);
    // Loops counter-clockwise seen from outside; normal and bit of each face.
    const std::uint32_t loops[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    const Vec3 normals[6] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
    for (int f = 0; f < 6; ++f) {
        hull->faces.push_back({normals[f], h, static_cast<std::uint32_t>(hull->faceIndices.size()), 4});
        for (const std::uint32_t v : loops[f]) hull->faceIndices.push_back(v);
    }
    hull->volume = 8 * h * h * h;
    hull->boundingRadius = h * std::sqrt(Real(3));
    return hull;
}

Quat randomRotation(std::mt19937& random) {
    std::normal_distribution<Real> gauss;
    return glm::normalize(Quat(gauss(random), gauss(random), gauss(random), gauss(random)));
}

/// Signed gap of two shapes: GJK's distance, or minus EPA's depth when they overlap, m.
Real signedGap(const Geometry& a, const Geometry& b) {
    const ConvexShape sa = convexShapeOf(a);
    const ConvexShape sb = convexShapeOf(b);
    const GjkResult g = gjk(sa, sb);
    if (!g.overlap) return g.distance;
    const EpaResult e = epa(sa, sb, g.simplex);
    return e.valid ? -e.depth : Real(0);
}

/// Moves B along a random direction from A until their gap is @p gap (bisection on signedGap()).
void placeAtGap(const Geometry& a, Geometry& b, Real gap, std::mt19937& random) {
    std::normal_distribution<Real> gauss;
    const Vec3 direction = glm::normalize(Vec3(gauss(random), gauss(random), gauss(random)));
    Real lo = 0, hi = 10;
    constexpr int kBisections = 50;  // 10 m / 2⁵⁰: far below a nanometre
    for (int i = 0; i < kBisections; ++i) {
        const Real mid = Real(0.5) * (lo + hi);
        b.centre = a.centre + direction * mid;
        (signedGap(a, b) < gap ? lo : hi) = mid;
    }
    b.centre = a.centre + direction * hi;
}

Geometry shapeOf(GeometryType type, std::mt19937& random, const ConvexHull& cube) {
    std::uniform_real_distribution<Real> size(Real(0.2), Real(0.8));
    Geometry g;
    g.type = type;
    g.orientation = randomRotation(random);
    g.halfExtents = Vec3(size(random), size(random), size(random));
    g.radius = Real(0.5) * size(random);
    g.halfHeight = size(random);
    g.hull = &cube;
    return g;
}

std::vector<Pair> pairSet(GeometryType ta, GeometryType tb, Real gapLow, Real gapHigh, int count, std::mt19937& random,
                          const ConvexHull& cube) {
    std::uniform_real_distribution<Real> gap(gapLow, gapHigh);
    std::vector<Pair> pairs;
    for (int i = 0; i < count; ++i) {
        Geometry a = shapeOf(ta, random, cube);
        Geometry b = shapeOf(tb, random, cube);
        placeAtGap(a, b, gap(random), random);
        pairs.emplace_back(a, b);
    }
    return pairs;
}

enum class Algorithm { Sat, ClosedForm, GjkEpa, Mpr };

const char* nameOf(Algorithm algorithm) {
    switch (algorithm) {
        case Algorithm::Sat: return "SAT";
        case Algorithm::ClosedForm: return "closed form";
        case Algorithm::GjkEpa: return "GJK+EPA";
        case Algorithm::Mpr: return "MPR";
    }
    return "";
}

/// One row: times each pass over @p pairs, prints the median and the iteration counts.
void row(const char* set, const std::vector<Pair>& pairs, Algorithm algorithm, const Options& options) {
    std::vector<double> passes;
    long contacts = 0;
    long sums[3] = {0, 0, 0};
    int maxima[3] = {0, 0, 0};
    for (int repeat = 0; repeat < options.repeats; ++repeat) {
        contacts = 0;
        const auto start = std::chrono::steady_clock::now();
        for (const Pair& pair : pairs) {
            ContactManifold m;
            bool touching = false;
            ConvexIterations n;
            switch (algorithm) {
                case Algorithm::Sat: touching = collideBoxBox(pair.first, pair.second, m); break;
                case Algorithm::ClosedForm:
                    touching = collideConvex(pair.first, pair.second, NarrowphaseKind::Auto, kSpeculativeDistance, m, &n);
                    break;
                case Algorithm::GjkEpa:
                    touching = collideConvex(pair.first, pair.second, NarrowphaseKind::GjkEpa, kSpeculativeDistance, m, &n);
                    break;
                case Algorithm::Mpr:
                    touching = collideConvex(pair.first, pair.second, NarrowphaseKind::Mpr, kSpeculativeDistance, m, &n);
                    break;
            }
            contacts += touching ? m.pointCount : 0;
            if (repeat == 0) {
                const int counts[3] = {n.gjk, n.epa, n.mpr};
                for (int k = 0; k < 3; ++k) {
                    sums[k] += counts[k];
                    maxima[k] = std::max(maxima[k], counts[k]);
                }
            }
        }
        const auto stop = std::chrono::steady_clock::now();
        passes.push_back(std::chrono::duration<double, std::nano>(stop - start).count() / static_cast<double>(pairs.size()));
    }
    std::nth_element(passes.begin(), passes.begin() + static_cast<long>(passes.size() / 2), passes.end());
    const double pairCount = static_cast<double>(pairs.size());
    std::printf("| %-22s | %-11s | %8.0f | %8ld |", set, nameOf(algorithm), passes[passes.size() / 2], contacts);
    for (int k = 0; k < 3; ++k) {
        if (maxima[k] == 0) {
            std::printf(" %12s |", "-");
        } else {
            std::printf(" %6.1f / %3d |", static_cast<double>(sums[k]) / pairCount, maxima[k]);
        }
    }
    std::printf("\n");
}

int usage(const char* message) {
    std::fprintf(stderr, "stepwise-bench narrowphase: error: %s\n\n%s", message, kNarrowphaseUsage);
    return 2;
}

bool parseCount(const std::string& text, int& value) {
    char* end = nullptr;
    const long n = std::strtol(text.c_str(), &end, 10);
    if (end == text.c_str() || *end != '\0' || n < 1 || n > 1000000) return false;
    value = static_cast<int>(n);
    return true;
}

}  // namespace

int narrowphaseCommand(const std::vector<std::string>& args) {
    Options options;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (arg == "--quick") {
            options.pairs = 200;
            options.repeats = 3;
        } else if (arg == "--pairs" || arg == "--repeats" || arg == "--seed") {
            if (i + 1 >= args.size()) return usage((arg + " needs a value").c_str());
            int value = 0;
            if (!parseCount(args[++i], value)) {
                return usage((arg + " expects a whole number from 1 to 1000000, found '" + args[i] + "'").c_str());
            }
            if (arg == "--pairs") options.pairs = value;
            else if (arg == "--repeats") options.repeats = value;
            else options.seed = static_cast<unsigned>(value);
        } else {
            return usage(("unknown option '" + arg + "'").c_str());
        }
    }

    std::mt19937 random(options.seed);
    const auto cube = cubeHull(Real(0.4));
    const auto boxesTouching = pairSet(GeometryType::Box, GeometryType::Box, Real(-0.05), Real(-0.001), options.pairs, random, *cube);
    const auto boxesApart = pairSet(GeometryType::Box, GeometryType::Box, Real(0.005), Real(0.05), options.pairs, random, *cube);
    const auto capsules = pairSet(GeometryType::Capsule, GeometryType::Capsule, Real(-0.05), Real(-0.001), options.pairs, random, *cube);
    const auto capsuleBox = pairSet(GeometryType::Capsule, GeometryType::Box, Real(-0.05), Real(-0.001), options.pairs, random, *cube);
    const auto cylinders = pairSet(GeometryType::Cylinder, GeometryType::Box, Real(-0.05), Real(-0.001), options.pairs, random, *cube);
    const auto hulls = pairSet(GeometryType::Hull, GeometryType::Hull, Real(-0.05), Real(-0.001), options.pairs, random, *cube);

    std::printf("Narrowphase side by side: %d pairs per set, median of %d passes, seed %u\n\n", options.pairs,
                options.repeats, options.seed);
    std::printf("| %-22s | %-11s | %8s | %8s | %12s | %12s | %12s |\n", "pairs", "algorithm", "ns/pair", "contacts",
                "GJK mean/max", "EPA mean/max", "MPR mean/max");
    std::printf("|------------------------|-------------|----------|----------|--------------|--------------|--------------|\n");
    for (const Algorithm algorithm : {Algorithm::Sat, Algorithm::GjkEpa, Algorithm::Mpr}) {
        row("box-box touching", boxesTouching, algorithm, options);
    }
    for (const Algorithm algorithm : {Algorithm::Sat, Algorithm::GjkEpa, Algorithm::Mpr}) {
        row("box-box apart", boxesApart, algorithm, options);
    }
    for (const Algorithm algorithm : {Algorithm::ClosedForm, Algorithm::GjkEpa, Algorithm::Mpr}) {
        row("capsule-capsule", capsules, algorithm, options);
    }
    for (const Algorithm algorithm : {Algorithm::GjkEpa, Algorithm::Mpr}) row("capsule-box", capsuleBox, algorithm, options);
    for (const Algorithm algorithm : {Algorithm::GjkEpa, Algorithm::Mpr}) row("cylinder-box", cylinders, algorithm, options);
    for (const Algorithm algorithm : {Algorithm::GjkEpa, Algorithm::Mpr}) row("hull-hull (cubes)", hulls, algorithm, options);
    std::printf("\nIterations: support queries per pair (GJK and MPR) and EPA's after its tetrahedron;\n"
                "'-': the algorithm did not run. A separated pair under MPR is measured by GJK.\n");
    return 0;
}

}  // namespace stepwise::bench
