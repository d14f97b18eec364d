#pragma once
// A child process spoken to in lines (POSIX pipes): the gate's timing workers
// (`probebench gate-worker`, GateWorker.h) and the callgrind run. The child's stderr is
// the gate's; its stdout carries only protocol lines.
#include <string>
#include <vector>

namespace pb::gate {

class WorkerProcess {
public:
    // Starts argv[0] (a path, or a name looked up in PATH) with `env` ("NAME=value") added to
    // this process's environment. `label` names it in errors. Throws pb::Error.
    WorkerProcess(const std::vector<std::string>& argv, const std::vector<std::string>& env,
                  std::string label);
    ~WorkerProcess(); // "quit", then waits; kills a child that does not exit
    WorkerProcess(const WorkerProcess&) = delete;
    WorkerProcess& operator=(const WorkerProcess&) = delete;

    // The next line the child writes (without the newline). Throws pb::Error when the child
    // exits first, or writes "error <text>" (the error becomes "<label>: <text>").
    std::string readLine();
    // Writes `line` and returns the reply line.
    std::string request(const std::string& line);
    const std::string& label() const { return label_; }

private:
    int pid_ = -1, toChild_ = -1, fromChild_ = -1;
    std::string label_, buffer_;
};

// Runs argv to completion with `env` added; returns its exit status (128 + signal when
// killed). Throws pb::Error when it cannot start.
int runProcess(const std::vector<std::string>& argv, const std::vector<std::string>& env);

// The path of the running executable (/proc/self/exe).
std::string selfExecutable();

} // namespace pb::gate
