// probebench stress: the numerical extremes (issue 8) - light levels, probe spacings, offsets
// from the origin, thin walls, tiny grids, one ray, resolutions, bad normals, zero variance,
// octahedral folds, invalid volumes - rendered with each variant and measured against the
// fp32 reference: NaN/Inf pixels, relative error, the switch that broke a case and the guard
// that fixes it (renderer/stress/). Built-in scenes and small bakes: minutes on 2 cores.
#include "CommandRegistry.h"
#include "JsonOption.h"
#include "PlatformOptions.h"
#include "ProfileOptions.h"
#include "core/Error.h"
#include "core/FileIO.h"
#include "gl/DebugOutput.h"
#include "image/Image.h"
#include "stress/StressReport.h"
#include "stress/gl/GlStressRenderer.h"

#include <cctype>
#include <chrono>
#include <filesystem>
#include <iostream>

namespace pb::app {
namespace {

struct StressArgs {
    platform::PlatformOptions platform;
    std::vector<std::string> variants, profiles, sets, cases;
    JsonOption json;
    std::string guards = "both", images;
    double threshold = 0.05;
    int width = 64, height = 48, maxResolution = 4096, rays = 64;
    bool listCases = false, noAnalysis = false;
};

// The variants to sweep: --variant specs (default: stress::defaultVariants()), each with
// every --set applied. Platform profiles (`--profiles a,b`) become variants here too: the
// profile's name and its switches, storage rgba16f unless the spec adds probes.format.
std::vector<stress::StressVariant> resolveVariants(const StressArgs& a) {
    std::vector<stress::StressVariant> out;
    for (const std::string& spec : a.variants)
        out.push_back(stress::parseVariantSpec(spec));
    for (const std::string& name : a.profiles) {
        const profile::PlatformProfile p = profile::loadProfile(name, profileSearch());
        stress::StressVariant v;
        v.name = p.name;
        v.profile = p.switches;
        out.push_back(v);
    }
    if (out.empty()) out = stress::defaultVariants();
    for (stress::StressVariant& v : out)
        for (const std::string& kv : a.sets) {
            const auto eq = kv.find('=');
            if (eq == std::string::npos || eq == 0)
                throw UsageError("--set '" + kv + "': expected key=value");
            v.set(kv.substr(0, eq), kv.substr(eq + 1), "--set");
        }
    for (std::size_t i = 0; i < out.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (out[i].name == out[j].name)
                throw Error("--variant: the name '" + out[i].name + "' is used twice");
    return out;
}

stress::RunGuards parseGuards(const std::string& s) {
    if (s == "as_given") return stress::RunGuards::AsGiven;
    if (s == "off") return stress::RunGuards::Off;
    if (s == "both") return stress::RunGuards::Both;
    throw UsageError("--guards '" + s + "': allowed values: as_given, off, both");
}

void validateStress(const StressArgs& a) {
    if (a.width < 1 || a.height < 1 || a.width > 4096 || a.height > 4096)
        throw UsageError("--width/--height must be in 1..4096");
    if (a.maxResolution < 1 || a.maxResolution > 16384)
        throw UsageError("--max-resolution must be in 1..16384");
    if (a.rays < 1 || a.rays > 4096) throw UsageError("--rays must be in 1..4096");
    if (!(a.threshold > 0.0) || a.threshold > 1e6)
        throw UsageError("--threshold must be a positive number");
}

int runStress(const StressArgs& a) {
    validateStress(a);
    const stress::RunGuards guards = parseGuards(a.guards);
    const std::vector<stress::StressVariant> variants = resolveVariants(a);
    stress::CaseOptions co;
    co.width = a.width;
    co.height = a.height;
    co.rays = a.rays;
    co.maxResolution = a.maxResolution;
    if (a.listCases) {
        for (const stress::StressCase& c : stress::stressCases(co))
            std::cout << c.name << "  (" << c.group << "): " << c.stresses << "\n";
        return 0;
    }
    stress::selectCases(stress::stressCases(co), a.cases); // names checked before any GL

    auto platform = platform::createPlatform(timingPlatform(a.platform));
    gl::DebugOutput debug;
    co.maxResolution = stress::largestStressResolution(a.maxResolution);
    const std::vector<stress::StressCase> cases =
        stress::selectCases(stress::stressCases(co), a.cases);
    stress::SweepOptions o;
    o.variants = variants;
    o.guards = guards;
    o.thresholds.medianRel = a.threshold;
    o.analyse = !a.noAnalysis;
    if (!a.images.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(a.images, ec);
        if (ec) throw fileError(a.images, "cannot create the folder: " + ec.message());
        o.onFrame = [&a](const std::string& c, const std::string& run,
                         const stress::RenderedFrame& f) {
            std::string name = c + "_" + run;
            for (char& ch : name)
                if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '.' && ch != '-')
                    ch = '_';
            image::writePng((std::filesystem::path(a.images) / (name + ".png")).string(), f.output);
        };
    }
    std::cerr << "stress: " << cases.size() << " case(s) x " << variants.size() << " variant(s)"
              << (guards == stress::RunGuards::Both ? " x guards as given and off" : "") << " on "
              << platform->description() << "\n";
    const auto t0 = std::chrono::steady_clock::now();
    stress::GlStressRenderer renderer(debug);
    renderer.setReadOutput(!a.images.empty());
    const stress::SweepResult r =
        stress::runSweep(cases, o, renderer, [&](const std::string& line) {
            const double s =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            std::cerr << "  " << int(s) << " s  " << line << "\n";
        });
    nlohmann::json j = stress::sweepJson(r);
    j["platform"] = platform->description();
    j["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (a.json) writeJson(a.json, j.dump(2) + "\n");
    std::cout << stress::sweepText(r);
    const auto& s = j["summary"];
    std::cout << "\n"
              << s["runs"] << " runs, " << s["broken"] << " broken (" << s["broken_with_guards"]
              << " with the guards as given; NaN/Inf pixels with guards: "
              << s["nonfinite_with_guards"] << "), " << s["frames"] << " frames in "
              << int(j["seconds"].get<double>()) << " s"
              << (a.json.file().empty() ? "" : "; wrote " + a.json.file()) << "\n";
    return 0;
}

const RegisterCommand registerStress{
    {"stress",
     "Sweep numerical extremes per variant: NaN/Inf, error vs fp32, the switch that breaks, the "
     "guard that fixes",
     55, [](CLI::App& cmd) {
         auto a = std::make_shared<StressArgs>();
         addPlatformOptions(cmd, a->platform);
         cmd.add_option("--variant", a->variants,
                        "NAME:key=value,... - switches (gi.*) and probes.format "
                        "(rgba16f|rgba32f|bc6h) of one variant (repeatable; default: defaults, "
                        "fp16, r11g11b10f, bc6h, quarter, handheld)");
         cmd.add_option("--profiles", a->profiles,
                        "Platform profiles (names or files, comma-separated) swept as variants "
                        "with their switches and rgba16f probes; with --variant, both")
             ->delimiter(',');
         cmd.add_option("--set", a->sets,
                        "key=value applied to every variant, not to the reference (repeatable)");
         cmd.add_option("--cases", a->cases,
                        "Cases or groups to run, comma-separated (default: all; --list-cases)")
             ->delimiter(',');
         cmd.add_flag("--list-cases", a->listCases, "Print the cases and exit");
         cmd.add_option("--guards", a->guards,
                        "Run each variant with its guards as given, with every gi.guard_* off, "
                        "or both")
             ->capture_default_str();
         cmd.add_option("--threshold", a->threshold,
                        "A run is broken when a pixel is NaN/Inf or the median relative error "
                        "passes this")
             ->capture_default_str();
         cmd.add_flag("--no-analysis", a->noAnalysis,
                      "Skip naming culprits and guards (fewer frames)");
         cmd.add_option("--width", a->width, "Frame width of the cases (resolution=* aside)")
             ->capture_default_str();
         cmd.add_option("--height", a->height, "Frame height of the cases")->capture_default_str();
         cmd.add_option("--max-resolution", a->maxResolution,
                        "Largest square of the resolution cases (also capped by the driver)")
             ->capture_default_str();
         cmd.add_option("--rays", a->rays, "Rays per probe of the cases' bakes")
             ->capture_default_str();
         a->json.add(cmd, "The full result");
         cmd.add_option("--images", a->images,
                        "Folder for the tonemapped frames: each case's reference and runs");
         return [a] {
             const StdoutToStderr textToStderr(a->json.toStdout());
             return runStress(*a);
         };
     }}};

} // namespace
} // namespace pb::app
