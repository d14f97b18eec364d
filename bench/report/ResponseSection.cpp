#include "ResponseSection.h"

#include "Format.h"
#include "Html.h"

#include <sstream>

namespace pb::bench {
namespace {

bool anyResponse(const BenchResult& r) {
    return r.response.is_object() && r.response.contains("profiles");
}

// The profile's own frame time (median, ms) from this run's sessions; "n/a" when not run.
std::string frameMs(const BenchResult& r, const std::string& profile) {
    for (const SessionResult& s : r.sessions)
        if (s.session.profile.name == profile && s.profile().ok())
            return fixed(s.profile().frameMs.median, 2);
    return "n/a";
}

// A settle frame, or "never" (null: not within the run's frames).
std::string frames(const nlohmann::json& v) {
    return v.is_number() ? std::to_string(v.get<long long>()) : "never";
}

// The profile's [update] budget: "no limit", or e.g. "4096 rays, any bytes".
std::string budget(const nlohmann::json& p) {
    auto part = [](const nlohmann::json& v) {
        return v.is_number() && v.get<double>() > 0 ? v.dump() : std::string("any");
    };
    const std::string rays = part(p.value("rays_per_frame_budget", nlohmann::json()));
    const std::string bytes = part(p.value("upload_bytes_per_frame_budget", nlohmann::json()));
    if (rays == "any" && bytes == "any") return "no limit";
    return rays + " rays, " + bytes + " bytes";
}

std::string events(const BenchResult& r) {
    std::string out;
    for (const auto& e : r.response.value("events", nlohmann::json::array())) {
        if (!out.empty()) out += ", ";
        out += e.get<std::string>();
    }
    return out;
}

std::string intro(const BenchResult& r) {
    const auto& j = r.response;
    return "event " + events(r) + ", " + j.value("frames", nlohmann::json()).dump() +
           " frames at " + j.value("width", nlohmann::json()).dump() + "x" +
           j.value("height", nlohmann::json()).dump() +
           " (probebench respond's measurement with each profile's switches and [update] budget; "
           "t95/t99: frames after the last event until the image error against the converged "
           "re-bake stays within 5%/1% of the step; never: not within the run)";
}

} // namespace

std::string responseMarkdown(const BenchResult& r) {
    if (!anyResponse(r)) return {};
    std::ostringstream out;
    out << "\nResponse to a scene change: " << intro(r) << ":\n\n"
        << "| profile | frame ms median | update budget per frame | schedule | response t95 "
           "(frames) | t99 (frames) | rays/frame | upload bytes/frame |\n"
        << "|---|---|---|---|---|---|---|---|\n";
    for (const auto& p : r.response["profiles"]) {
        const std::string name = p.value("profile", std::string("?"));
        if (p.contains("not_run")) {
            out << "| " << name << " | n/a | - | not run: " << p["not_run"].get<std::string>()
                << " | - | - | - | - |\n";
            continue;
        }
        for (const auto& s : p.value("schedules", nlohmann::json::array()))
            out << "| " << name << " | " << frameMs(r, name) << " | " << budget(p) << " | "
                << s.value("schedule", std::string("?")) << " | " << frames(s["t95_frames"])
                << " | " << frames(s["t99_frames"]) << " | "
                << fixed(s.value("rays_per_frame", 0.0), 0) << " | "
                << fixed(s.value("upload_bytes_per_frame", 0.0), 0) << " |\n";
    }
    return out.str();
}

std::string responseHtml(const BenchResult& r) {
    if (!anyResponse(r)) return {};
    std::ostringstream h;
    h << "<h2>Response to a scene change</h2>\n<p class=\"note\">" << htmlEscape(intro(r))
      << ".</p>\n<table id=\"response\"><tr><th class=\"l\">profile</th><th>frame ms "
         "median</th><th>update budget per frame</th><th class=\"l\">schedule</th><th>response "
         "t95 (frames)</th><th>t99 (frames)</th><th>rays/frame</th><th>upload "
         "bytes/frame</th></tr>\n";
    auto cell = [](const std::string& text, const char* cls = "") {
        return std::string("<td class=\"") + cls + "\">" + htmlEscape(text) + "</td>";
    };
    for (const auto& p : r.response["profiles"]) {
        const std::string name = p.value("profile", std::string("?"));
        if (p.contains("not_run")) {
            h << "<tr>" << cell(name, "l") << "<td class=\"l bad\" colspan=\"7\">not run: "
              << htmlEscape(p["not_run"].get<std::string>()) << "</td></tr>\n";
            continue;
        }
        for (const auto& s : p.value("schedules", nlohmann::json::array()))
            h << "<tr>" << cell(name, "l") << cell(frameMs(r, name)) << cell(budget(p))
              << cell(s.value("schedule", std::string("?")), "l") << cell(frames(s["t95_frames"]))
              << cell(frames(s["t99_frames"])) << cell(fixed(s.value("rays_per_frame", 0.0), 0))
              << cell(fixed(s.value("upload_bytes_per_frame", 0.0), 0)) << "</tr>\n";
    }
    h << "</table>\n";
    return h.str();
}

} // namespace pb::bench
