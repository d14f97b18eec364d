#include "SweepMerge.h"

#include "core/Error.h"
#include "core/FileIO.h"
#include "bench/report/Format.h"
#include "bench/report/Html.h"

#include <filesystem>
#include <map>
#include <set>
#include <sstream>

namespace pb::sweep {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// Every string that starts with `prefix` loses it (absolute paths of the output folder
// become relative, so two folders' results compare equal).
void relativise(json& j, const std::string& prefix) {
    if (j.is_string()) {
        const std::string s = j.get<std::string>();
        if (s.rfind(prefix, 0) == 0) j = s.substr(prefix.size());
    } else if (j.is_structured()) {
        for (json& e : j)
            relativise(e, prefix);
    }
}

json readJobOutput(const std::string& outDir, const SweepJob& job) {
    const std::string path = (fs::path(outDir) / job.output).string();
    if (!fs::exists(path)) throw fileError(path, "job " + std::to_string(job.index) + "'s output is missing");
    const std::vector<unsigned char> bytes = readFileBytes(path);
    try {
        return json::parse(bytes.begin(), bytes.end());
    } catch (const json::exception&) {
        throw fileError(path, "job " + std::to_string(job.index) + "'s output is not JSON");
    }
}

bool isTimingKey(const std::string& k) {
    static const std::set<std::string> named = {
        "context", "node", "nodes", "seconds", "ms", "bimodality_coefficient", "gi_over_floor",
        "noise_flags", "frame_within",
        // the machine's state while timing (load, steal, other processes): of the run, not of
        // the result
        "machine", "machine_warning"};
    return named.count(k) > 0 || (k.size() > 3 && k.compare(k.size() - 3, 3, "_ms") == 0);
}

std::string text(const json& j) {
    if (j.is_string()) return j.get<std::string>();
    if (j.is_null()) return "";
    return j.dump();
}

// A bench job's row: what the Markdown and HTML tables show.
struct Row {
    std::size_t job = 0;
    std::string scene, profile, resolution, switches, status;
    double medianMs = 0, flipMean = 0, psnr = 0, giMib = 0;
    bool measured = false, psnrFinite = false;
};

std::vector<Row> rowsOf(const json& merged, const std::string& node) {
    std::vector<Row> rows;
    for (const json& p : merged.at("profiles")) {
        if (p.at("node").get<std::string>() != node) continue;
        Row r;
        r.job = p.at("job").get<std::size_t>();
        r.scene = text(p.at("labels").at("scene"));
        r.profile = p.at("name").get<std::string>();
        r.resolution = text(p.at("labels").at("resolution"));
        for (const json& s : p.at("labels").at("switches")) {
            // Two appends, not a chain of +: GCC 12 warns (falsely) about the chain's copy.
            if (!r.switches.empty()) r.switches += ' ';
            r.switches += s.get<std::string>();
        }
        r.status = text(p.at("status"));
        if (p.contains("frame_ms")) {
            r.measured = true;
            r.medianMs = p.at("frame_ms").at("median").get<double>();
            r.giMib = p.at("gi_memory_mib").get<double>();
            const json& a = p.at("accuracy");
            r.flipMean = a.value("flip_mean", 0.0);
            r.psnrFinite = a.contains("psnr_db") && a.at("psnr_db").is_number();
            r.psnr = r.psnrFinite ? a.at("psnr_db").get<double>() : 0.0;
        }
        rows.push_back(r);
    }
    return rows;
}

std::string nodeNote(const json& merged) {
    const std::string cls = merged.at("plan").at("node_class").get<std::string>();
    if (!cls.empty())
        return "The plan names one node class (" + cls +
               "): frame times of different nodes are comparable.";
    return "Frame times are grouped by node and compare only within a node (each job's ratios "
           "hold within its own interleaved rounds); the plan names no node class.";
}

} // namespace

json mergeSweep(const PlanState& plan, const std::string& outDir, const json& bakes) {
    const std::string prefix = canonicalDir(outDir) + "/";
    json merged{{"schema", "probebench.sweep/1"},
                {"bench_schema", "probebench.bench/1"},
                {"plan",
                 {{"name", plan.name},
                  {"plan_id", plan.id},
                  {"node_class", plan.nodeClass},
                  {"jobs", plan.jobs.size()},
                  {"chunk", plan.chunk}}}};
    json jobs = json::array(), profiles = json::array(), variants = json::array();
    json nodes = json::object();
    double seconds = 0.0, heatmapScale = 0.0;
    bool haveBench = false;
    for (const SweepJob& job : plan.jobs) {
        const std::optional<JobStatus> st = readJobStatus(outDir, job.index);
        if (!st || st->exitCode != 0)
            throw Error("sweep: job " + std::to_string(job.index) + " has not finished cleanly; " +
                        "nothing merged (--resume runs it again)");
        json entry = jobJson(job);
        entry["node"] = st->node;
        entry["seconds"] = st->seconds;
        seconds += st->seconds;
        if (!nodes.contains(st->node)) nodes[st->node] = {{"jobs", json::array()}};
        nodes[st->node]["jobs"].push_back(job.index);
        if (job.kind == "bench" || job.kind == "command") {
            json result = readJobOutput(outDir, job);
            relativise(result, prefix);
            if (job.kind == "bench") {
                if (!haveBench) {
                    for (const char* k : {"context", "scene", "view", "settings"})
                        merged[k] = result.value(k, json());
                    haveBench = true;
                }
                heatmapScale = std::max(heatmapScale, result.value("heatmap_scale", 0.0));
                if (!nodes[st->node].contains("cpu") && result.contains("context"))
                    nodes[st->node]["cpu"] = result["context"].value("cpu", json());
                for (const char* list : {"profiles", "variants"})
                    for (json e : result.value(list, json::array())) {
                        e["job"] = job.index;
                        e["node"] = st->node;
                        e["labels"] = job.labels;
                        (std::string(list) == "profiles" ? profiles : variants).push_back(e);
                    }
            }
            entry["result"] = std::move(result);
        }
        jobs.push_back(std::move(entry));
    }
    if (!haveBench)
        for (const char* k : {"context", "scene", "view", "settings"})
            merged[k] = nullptr;
    merged["heatmap_scale"] = heatmapScale;
    merged["seconds"] = seconds;
    merged["profiles"] = profiles;
    merged["variants"] = variants;
    merged["nodes"] = nodes;
    merged["bakes"] = bakes;
    merged["jobs"] = jobs;
    return merged;
}

json withoutTimings(const json& j) {
    if (j.is_object()) {
        json out = json::object();
        for (auto it = j.begin(); it != j.end(); ++it)
            if (!isTimingKey(it.key())) out[it.key()] = withoutTimings(it.value());
        return out;
    }
    if (j.is_array()) {
        json out = json::array();
        for (const json& e : j)
            out.push_back(withoutTimings(e));
        return out;
    }
    return j;
}

std::string sweepMarkdown(const json& merged) {
    std::ostringstream md;
    const json& plan = merged.at("plan");
    md << "# Sweep `" << plan.at("name").get<std::string>() << "` (plan "
       << plan.at("plan_id").get<std::string>() << ", " << plan.at("jobs").get<std::size_t>()
       << " jobs)\n\n"
       << nodeNote(merged) << "\n";
    for (auto it = merged.at("nodes").begin(); it != merged.at("nodes").end(); ++it) {
        const std::vector<Row> rows = rowsOf(merged, it.key());
        md << "\n## Node " << it.key();
        if (it.value().contains("cpu")) md << " (" << text(it.value()["cpu"]) << ")";
        md << ": " << it.value().at("jobs").size() << " job(s)\n\n";
        if (rows.empty()) {
            md << "No bench job ran here.\n";
            continue;
        }
        md << "| job | scene | profile | switches | size | frame ms (median) | FLIP mean | PSNR dB "
              "| GI MiB |\n|---|---|---|---|---|---|---|---|---|\n";
        for (const Row& r : rows) {
            md << "| " << r.job << " | " << r.scene << " | " << r.profile << " | "
               << (r.switches.empty() ? "-" : r.switches) << " | " << r.resolution << " | ";
            if (r.measured)
                md << bench::fixed(r.medianMs, 2) << " | " << bench::fixed(r.flipMean, 4) << " | "
                   << (r.psnrFinite ? bench::fixed(r.psnr, 2) : "inf") << " | "
                   << bench::fixed(r.giMib, 2) << " |\n";
            else
                md << r.status << " | | | |\n";
        }
    }
    if (!merged.at("bakes").empty()) {
        md << "\n## Split bakes\n\n| scene | parts | merged file | bytes | FNV-1a |\n"
              "|---|---|---|---|---|\n";
        for (const json& b : merged.at("bakes"))
            md << "| " << text(b.at("scene")) << " | " << b.at("parts").get<int>() << " | "
               << text(b.at("file")) << " | " << b.at("bytes").get<std::uint64_t>() << " | "
               << text(b.at("fnv1a64")) << " |\n";
    }
    return md.str();
}

std::string sweepHtml(const json& merged) {
    using bench::htmlEscape;
    std::ostringstream h;
    const json& plan = merged.at("plan");
    h << "<!doctype html>\n<html><head><meta charset=\"utf-8\"><title>Sweep "
      << htmlEscape(plan.at("name").get<std::string>())
      << "</title><style>body{font-family:sans-serif;margin:2em}table{border-collapse:collapse}"
         "td,th{border:1px solid #bbb;padding:2px 8px;text-align:right}"
         "td:nth-child(-n+5),th{text-align:left}</style></head><body>\n<h1>Sweep "
      << htmlEscape(plan.at("name").get<std::string>()) << "</h1>\n<p>Plan "
      << htmlEscape(plan.at("plan_id").get<std::string>()) << ", "
      << plan.at("jobs").get<std::size_t>() << " jobs. " << htmlEscape(nodeNote(merged))
      << "</p>\n";
    for (auto it = merged.at("nodes").begin(); it != merged.at("nodes").end(); ++it) {
        const std::vector<Row> rows = rowsOf(merged, it.key());
        h << "<h2>Node " << htmlEscape(it.key());
        if (it.value().contains("cpu")) h << " (" << htmlEscape(text(it.value()["cpu"])) << ")";
        h << "</h2>\n";
        if (rows.empty()) {
            h << "<p>No bench job ran here.</p>\n";
            continue;
        }
        h << "<table><tr><th>job</th><th>scene</th><th>profile</th><th>switches</th><th>size</th>"
             "<th>frame ms (median)</th><th>FLIP mean</th><th>PSNR dB</th><th>GI MiB</th></tr>\n";
        for (const Row& r : rows) {
            h << "<tr><td>" << r.job << "</td><td>" << htmlEscape(r.scene) << "</td><td>"
              << htmlEscape(r.profile) << "</td><td>" << htmlEscape(r.switches) << "</td><td>"
              << htmlEscape(r.resolution) << "</td>";
            if (r.measured)
                h << "<td>" << bench::fixed(r.medianMs, 2) << "</td><td>"
                  << bench::fixed(r.flipMean, 4) << "</td><td>"
                  << (r.psnrFinite ? bench::fixed(r.psnr, 2) : "inf") << "</td><td>"
                  << bench::fixed(r.giMib, 2) << "</td></tr>\n";
            else
                h << "<td colspan=\"4\">" << htmlEscape(r.status) << "</td></tr>\n";
        }
        h << "</table>\n";
    }
    if (!merged.at("bakes").empty()) {
        h << "<h2>Split bakes</h2>\n<table><tr><th>scene</th><th>parts</th><th>merged file</th>"
             "<th>bytes</th><th>FNV-1a</th></tr>\n";
        for (const json& b : merged.at("bakes"))
            h << "<tr><td>" << htmlEscape(text(b.at("scene"))) << "</td><td>"
              << b.at("parts").get<int>() << "</td><td>" << htmlEscape(text(b.at("file")))
              << "</td><td>" << b.at("bytes").get<std::uint64_t>() << "</td><td>"
              << htmlEscape(text(b.at("fnv1a64"))) << "</td></tr>\n";
        h << "</table>\n";
    }
    h << "<p>Every job's full result, its command line and node are in the sweep's JSON.</p>\n"
         "</body></html>\n";
    return h.str();
}

} // namespace pb::sweep
