// probebench compare: image-error metrics (PSNR, SSIM, LDR-FLIP) of a test PNG against a
// reference PNG, optionally with a FLIP heat map. GL-free.
#include "CommandRegistry.h"
#include "OutputPaths.h"
#include "JsonOption.h"
#include "NumberChecks.h"
#include "core/Error.h"
#include "image/Image.h"
#include "metrics/ImageMetrics.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

namespace pb::app {
namespace {

struct CompareArgs {
    std::string test, reference, heatmap;
    double ppd = 67.0;
    bool mkdir = false; // --mkdir: create --heatmap's and --json's folders
    JsonOption json;
};

std::string size(const image::Image8& img) {
    return std::to_string(img.width) + "x" + std::to_string(img.height);
}

int runCompare(const CompareArgs& a) {
    if (!a.heatmap.empty()) prepareOutputParent("--heatmap", a.heatmap, a.mkdir); // OutputPaths.h
    const image::Image8 test = image::readPng(a.test);
    const image::Image8 reference = image::readPng(a.reference);
    if (test.width != reference.width || test.height != reference.height)
        throw Error(a.test + ": size " + size(test) + " differs from the reference " + a.reference +
                    " (" + size(reference) + ")");
    const double psnr = metrics::psnr(test, reference);
    const double ssim = metrics::ssim(test, reference);
    const metrics::FlipResult flip = metrics::ldrFlip(test, reference, a.ppd);
    // Everything is computed before anything is written: a failure leaves no output behind.
    if (!a.heatmap.empty()) image::writePng(a.heatmap, metrics::errorHeatMap(flip.map));

    const bool identical = std::isinf(psnr);
    if (a.json) {
        nlohmann::json j = {{"test", a.test},
                            {"reference", a.reference},
                            {"width", test.width},
                            {"height", test.height},
                            {"ppd", a.ppd},
                            {"identical", identical},
                            // JSON has no infinity: identical images give null.
                            {"psnr_db", identical ? nlohmann::json(nullptr) : nlohmann::json(psnr)},
                            {"ssim", ssim},
                            {"flip_mean", flip.mean},
                            {"flip_max", flip.max}};
        if (!a.heatmap.empty()) j["heatmap"] = a.heatmap;
        writeJson(a.json, j.dump(2) + "\n");
        return 0;
    }
    char line[128];
    std::cout << "test       " << a.test << " (" << size(test) << ")\n"
              << "reference  " << a.reference << "\n";
    if (identical)
        std::cout << "PSNR       inf dB (identical)\n";
    else {
        std::snprintf(line, sizeof line, "PSNR       %.3f dB\n", psnr);
        std::cout << line;
    }
    std::snprintf(line, sizeof line, "SSIM       %.5f\n", ssim);
    std::cout << line;
    std::snprintf(line, sizeof line, "FLIP       mean %.5f  max %.5f  (%.1f pixels per degree)\n",
                  flip.mean, flip.max, a.ppd);
    std::cout << line;
    if (!a.heatmap.empty()) std::cout << "heat map   " << a.heatmap << "\n";
    return 0;
}

const RegisterCommand registerCompare{{
    "compare",
    "Image error of a test PNG against a reference PNG: PSNR, SSIM, LDR-FLIP (+ heat map)",
    60,
    [](CLI::App& cmd) -> std::function<int()> {
        auto a = std::make_shared<CompareArgs>();
        cmd.add_option("--test", a->test, "The image to judge (8-bit sRGB PNG)")->required();
        cmd.add_option("--reference", a->reference,
                       "The reference image (8-bit sRGB PNG, same size as --test)")
            ->required();
        cmd.add_option("--ppd", a->ppd,
                       "Viewing condition for FLIP in pixels per degree of visual angle "
                       "(default 67: a 0.7 m wide 4K screen seen from 0.7 m)")
            ->check(numberAtLeastZero(true));
        cmd.add_option("--heatmap", a->heatmap,
                       "Write the per-pixel FLIP error as a PNG heat map (black = no error, "
                       "pale yellow = 1)");
        cmd.add_flag("--mkdir", a->mkdir, "Create the missing parent folder of --heatmap and --json (else a missing folder is an error, before any work)");
        a->json.add(cmd, "The metrics (psnr_db is null for identical images, see \"identical\")");
        return [a] { return runCompare(*a); };
    },
}};

} // namespace
} // namespace pb::app
