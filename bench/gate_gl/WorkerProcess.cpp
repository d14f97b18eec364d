#include "WorkerProcess.h"

#include "core/Error.h"

#include <csignal>
#include <cstring>
#include <filesystem>
#include <sys/wait.h>
#include <unistd.h>

namespace pb::gate {

namespace {

// fork + exec with the environment extended; stdin/stdout redirected when the fds are >= 0.
int spawn(const std::vector<std::string>& argv, const std::vector<std::string>& env, int in,
          int out, int closeInChild[2]) {
    if (argv.empty()) throw Error("no command to run");
    std::vector<char*> args;
    for (const std::string& a : argv)
        args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    const pid_t pid = fork();
    if (pid < 0) throw Error(argv[0] + ": cannot start a process: " + std::strerror(errno));
    if (pid == 0) {
        if (in >= 0) dup2(in, STDIN_FILENO);
        if (out >= 0) dup2(out, STDOUT_FILENO);
        for (int i = 0; i < 2; ++i)
            if (closeInChild && closeInChild[i] >= 0) close(closeInChild[i]);
        if (in >= 0) close(in);
        if (out >= 0) close(out);
        for (const std::string& e : env)
            putenv(const_cast<char*>(e.c_str()));
        execvp(args[0], args.data());
        const std::string msg = "error cannot run " + argv[0] + ": " + std::strerror(errno) + "\n";
        if (write(STDOUT_FILENO, msg.data(), msg.size()) < 0) {
        }
        _exit(127);
    }
    return int(pid);
}

} // namespace

WorkerProcess::WorkerProcess(const std::vector<std::string>& argv,
                             const std::vector<std::string>& env, std::string label)
    : label_(std::move(label)) {
    int down[2], up[2]; // parent -> child, child -> parent
    if (pipe(down) != 0 || pipe(up) != 0) throw Error(label_ + ": cannot create pipes");
    int parentEnds[2] = {down[1], up[0]};
    pid_ = spawn(argv, env, down[0], up[1], parentEnds);
    close(down[0]);
    close(up[1]);
    toChild_ = down[1];
    fromChild_ = up[0];
    std::signal(SIGPIPE, SIG_IGN); // a dead worker is an error reply, not a signal
}

WorkerProcess::~WorkerProcess() {
    if (toChild_ >= 0) {
        const char quit[] = "quit\n";
        if (write(toChild_, quit, sizeof quit - 1) < 0) {
        }
        close(toChild_);
    }
    if (fromChild_ >= 0) close(fromChild_);
    if (pid_ > 0) {
        int status = 0;
        for (int i = 0; i < 100; ++i) { // up to 10 s for a clean exit
            if (waitpid(pid_, &status, WNOHANG) == pid_) return;
            usleep(100000);
        }
        kill(pid_, SIGKILL);
        waitpid(pid_, &status, 0);
    }
}

std::string WorkerProcess::readLine() {
    while (true) {
        const size_t nl = buffer_.find('\n');
        if (nl != std::string::npos) {
            std::string line = buffer_.substr(0, nl);
            buffer_.erase(0, nl + 1);
            if (line.rfind("error ", 0) == 0) throw Error(label_ + ": " + line.substr(6));
            return line;
        }
        char chunk[4096];
        const ssize_t n = read(fromChild_, chunk, sizeof chunk);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            int status = 0;
            waitpid(pid_, &status, 0);
            pid_ = -1;
            throw Error(label_ + ": the worker exited (" +
                        (WIFEXITED(status) ? "status " + std::to_string(WEXITSTATUS(status))
                                           : "signal " + std::to_string(WTERMSIG(status))) +
                        ") before answering; does it have `probebench gate-worker`?");
        }
        buffer_.append(chunk, size_t(n));
    }
}

std::string WorkerProcess::request(const std::string& line) {
    const std::string l = line + "\n";
    if (write(toChild_, l.data(), l.size()) != ssize_t(l.size()))
        throw Error(label_ + ": the worker stopped listening");
    return readLine();
}

int runProcess(const std::vector<std::string>& argv, const std::vector<std::string>& env) {
    const int pid = spawn(argv, env, -1, -1, nullptr);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) throw Error(argv[0] + ": lost the process");
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

std::string selfExecutable() {
    std::error_code ec;
    const auto p = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) throw Error("cannot find the running executable (/proc/self/exe)");
    return p.string();
}

} // namespace pb::gate
