#include "SweepState.h"

#include "core/Error.h"
#include "core/FileIO.h"

#include <cstdio>
#include <deque>
#include <filesystem>
#include <fstream>

namespace pb::sweep {
namespace fs = std::filesystem;

namespace {

void writeJson(const std::string& path, const nlohmann::json& j) {
    fs::create_directories(fs::path(path).parent_path());
    const std::string text = j.dump(2) + "\n";
    writeFileAtomic(path, text.data(), text.size());
}

} // namespace

std::string canonicalDir(const std::string& dir) {
    std::string s = fs::absolute(dir).lexically_normal().string();
    while (s.size() > 1 && s.back() == '/')
        s.pop_back();
    return s;
}

std::string planStatePath(const std::string& outDir) {
    return (fs::path(outDir) / "sweep-plan.json").string();
}
std::string statusPath(const std::string& outDir, std::size_t job) {
    return (fs::path(outDir) / "status" / (jobNumberText(job) + ".json")).string();
}
std::string logPath(const std::string& outDir, std::size_t job, const char* stream) {
    return (fs::path(outDir) / "logs" / (jobNumberText(job) + "." + stream)).string();
}

void writePlanState(const std::string& outDir, const PlanState& s) {
    nlohmann::json jobs = nlohmann::json::array();
    for (const SweepJob& j : s.jobs)
        jobs.push_back(jobJson(j));
    writeJson(planStatePath(outDir), {{"schema", "probebench.sweep-plan/1"},
                                      {"name", s.name},
                                      {"plan_id", s.id},
                                      {"node_class", s.nodeClass},
                                      {"chunk", s.chunk},
                                      {"jobs", jobs}});
}

std::optional<PlanState> readPlanState(const std::string& outDir) {
    const std::string path = planStatePath(outDir);
    if (!fs::exists(path)) return std::nullopt;
    try {
        const std::vector<unsigned char> bytes = readFileBytes(path);
        const nlohmann::json j = nlohmann::json::parse(bytes.begin(), bytes.end());
        PlanState s;
        s.name = j.at("name").get<std::string>();
        s.id = j.at("plan_id").get<std::string>();
        s.nodeClass = j.at("node_class").get<std::string>();
        s.chunk = j.at("chunk").get<std::size_t>();
        for (const nlohmann::json& job : j.at("jobs"))
            s.jobs.push_back(jobFromJson(job));
        if (s.chunk < 1 || s.jobs.empty()) throw Error("no jobs or chunk 0");
        return s;
    } catch (const nlohmann::json::exception& e) {
        throw fileError(path, std::string("corrupt sweep state: ") + e.what());
    } catch (const Error& e) {
        throw fileError(path, std::string("corrupt sweep state: ") + e.what());
    }
}

void writeJobStatus(const std::string& outDir, const JobStatus& s) {
    writeJson(statusPath(outDir, s.index), {{"index", s.index},
                                            {"exit_code", s.exitCode},
                                            {"node", s.node},
                                            {"seconds", s.seconds}});
}

std::optional<JobStatus> readJobStatus(const std::string& outDir, std::size_t job) {
    const std::string path = statusPath(outDir, job);
    if (!fs::exists(path)) return std::nullopt;
    try {
        const std::vector<unsigned char> bytes = readFileBytes(path);
        const nlohmann::json j = nlohmann::json::parse(bytes.begin(), bytes.end());
        return JobStatus{j.at("index").get<std::size_t>(), j.at("exit_code").get<int>(),
                         j.at("node").get<std::string>(), j.at("seconds").get<double>()};
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

std::vector<std::size_t> unfinishedJobs(const std::string& outDir, const PlanState& s) {
    std::vector<std::size_t> out;
    for (const SweepJob& j : s.jobs) {
        const std::optional<JobStatus> st = readJobStatus(outDir, j.index);
        if (!st || st->exitCode != 0) out.push_back(j.index);
    }
    return out;
}

std::vector<std::size_t> unfinishedTasks(const std::string& outDir, const PlanState& s) {
    std::vector<std::size_t> tasks;
    for (std::size_t j : unfinishedJobs(outDir, s))
        if (tasks.empty() || tasks.back() != j / s.chunk) tasks.push_back(j / s.chunk);
    return tasks;
}

std::string indexRanges(const std::vector<std::size_t>& indices) {
    std::string out;
    for (std::size_t i = 0; i < indices.size();) {
        std::size_t j = i;
        while (j + 1 < indices.size() && indices[j + 1] == indices[j] + 1)
            ++j;
        if (!out.empty()) out += ",";
        out += std::to_string(indices[i]);
        if (j > i) {
            out += '-'; // two appends, not "-" + ...: GCC 12 warns (falsely) about that
            out += std::to_string(indices[j]);
        }
        i = j + 1;
    }
    return out;
}

std::string tailOfFile(const std::string& path, std::size_t lines) {
    std::ifstream in(path);
    std::deque<std::string> last;
    for (std::string line; std::getline(in, line);) {
        last.push_back(line);
        if (last.size() > lines) last.pop_front();
    }
    std::string out;
    for (const std::string& l : last)
        out += l + "\n";
    return out;
}

} // namespace pb::sweep
