#include "GateWorker.h"

#include "GateTiming.h"
#include "WorkerProcess.h"
#include "core/Error.h"

#include <istream>
#include <map>
#include <memory>
#include <ostream>
#include <sstream>

namespace pb::gate {

int serveGateWorker(const WorkerOptions& o, std::istream& in, std::ostream& out) {
    std::map<std::string, std::unique_ptr<GateRenderer>> renderers;
    try {
        bench::SectionTimer timer(o.timing, o.es);
        out << kWorkerHello << std::endl;
        std::string line;
        while (std::getline(in, line)) {
            std::istringstream words(line);
            std::string cmd, name;
            words >> cmd >> name;
            if (cmd == "quit") return 0;
            if (cmd == "load") {
                renderers[name] =
                    std::make_unique<GateRenderer>(o.inputs, profile::loadProfile(name, o.search));
                out << "ok" << std::endl;
            } else if (cmd == "round") {
                int frames = 0;
                words >> frames;
                auto it = renderers.find(name);
                if (it == renderers.end()) throw Error("round before load of '" + name + "'");
                if (frames < 1 || frames > 1000) throw Error("round: frames must be in 1..1000");
                const RoundTimes t = timeRound(*it->second, timer, frames);
                char reply[96];
                std::snprintf(reply, sizeof reply, "times %.6f %.6f", t.frameMs, t.giMs);
                out << reply << std::endl;
            } else {
                throw Error("unknown request '" + line + "'");
            }
        }
        return 0; // the gate closed the pipe
    } catch (const std::exception& e) {
        std::string msg = e.what();
        for (char& c : msg)
            if (c == '\n') c = ' ';
        out << "error " << msg << std::endl;
        return 1;
    }
}

void checkWorkerHello(const std::string& hello, const std::string& label) {
    if (hello == kWorkerHello) return;
    const std::string prefix = "ready probebench-gate-worker/";
    if (hello.rfind(prefix, 0) != 0) throw Error(label + ": not a probebench gate worker");
    const std::string mine = std::string(kWorkerHello).substr(prefix.size());
    throw Error(label + ": speaks gate-worker protocol " + hello.substr(prefix.size()) +
                ", this gate " + mine +
                " (protocol 1 timed only the gi-* passes as GI; 2 the passes of "
                "bench/report/GiSections.h, upsample included): build both binaries from "
                "commits with the same protocol");
}

namespace {

RoundTimes askRound(WorkerProcess& w, const std::string& profile, int frames) {
    const std::string reply = w.request("round " + profile + " " + std::to_string(frames));
    std::istringstream in(reply);
    std::string word;
    RoundTimes t;
    if (!(in >> word >> t.frameMs >> t.giMs) || word != "times")
        throw Error(w.label() + ": unexpected reply '" + reply + "'");
    return t;
}

} // namespace

SequentialTiming timeAgainst(WorkerProcess& baseline, WorkerProcess& candidate,
                             const std::string& profile, const TimingSettings& s, int budget,
                             double timeBudgetSeconds,
                             const std::function<void(const std::string&)>& progress) {
    for (WorkerProcess* w : {&baseline, &candidate})
        if (const std::string r = w->request("load " + profile); r != "ok")
            throw Error(w->label() + ": unexpected reply '" + r + "'");
    auto measure = [&](int round) {
        RoundTimes a, b;
        if (round % 2 == 0) {
            a = askRound(baseline, profile, s.frames);
            b = askRound(candidate, profile, s.frames);
        } else {
            b = askRound(candidate, profile, s.frames);
            a = askRound(baseline, profile, s.frames);
        }
        return std::vector<std::pair<double, double>>{{a.frameMs, b.frameMs}, {a.giMs, b.giMs}};
    };
    return runSequential({"frame", "gi"}, measure, {}, true, s, s.threshold, budget,
                         timeBudgetSeconds, progress);
}

} // namespace pb::gate
