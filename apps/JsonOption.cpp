#include "JsonOption.h"

#include "OutputPaths.h"

#include "core/Error.h"
#include "core/FileIO.h"

#include <cstdio>
#include <iostream>
#include <unistd.h>

namespace pb::app {
namespace {

int realStdout = -1; // the saved stdout while a StdoutToStderr is alive

void flushBoth() {
    std::cout.flush();
    std::fflush(stdout);
}

} // namespace

void JsonOption::add(CLI::App& cmd, const std::string& what) {
    option_ = cmd.add_option("--json", value_,
                             what +
                                 " as JSON: to FILE, or to stdout without one or with '-' "
                                 "(the text for people then goes to stderr)")
                  ->expected(0, 1)
                  ->type_name("[FILE]");
    // The one output-folder rule (OutputPaths.h): FILE's folder is checked once the command
    // line is parsed, before the command does any work; --mkdir creates it. A command that
    // writes other files has its own --mkdir (added before this) covering them too.
    const CLI::Option* mkdir = cmd.get_option_no_throw("--mkdir");
    if (!mkdir)
        mkdir = cmd.add_flag("--mkdir", mkdir_,
                             "Create the missing parent folders of the --json FILE (else a "
                             "missing folder is an error, before any work)");
    cmd.parse_complete_callback([this, mkdir] {
        if (!file().empty()) prepareOutputParent("--json", file(), mkdir->count() > 0);
    });
}

void writeJson(const JsonOption& json, const std::string& text) {
    if (!json.toStdout()) {
        writeFileAtomic(json.file(), text.data(), text.size());
        return;
    }
    flushBoth();
    if (realStdout < 0) {
        std::cout << text;
        std::cout.flush();
        return;
    }
    for (std::size_t done = 0; done < text.size();) {
        const ssize_t n = ::write(realStdout, text.data() + done, text.size() - done);
        if (n <= 0) throw Error("--json: cannot write to stdout");
        done += std::size_t(n);
    }
}

StdoutToStderr::StdoutToStderr(bool active) {
    if (!active || realStdout >= 0) return;
    flushBoth();
    saved_ = ::dup(STDOUT_FILENO);
    if (saved_ < 0 || ::dup2(STDERR_FILENO, STDOUT_FILENO) < 0) {
        if (saved_ >= 0) ::close(saved_);
        saved_ = -1;
        return; // stdout stays as it was: the JSON then shares it with the text
    }
    realStdout = saved_;
}

StdoutToStderr::~StdoutToStderr() {
    if (saved_ < 0) return;
    flushBoth();
    ::dup2(saved_, STDOUT_FILENO);
    ::close(saved_);
    realStdout = -1;
}

} // namespace pb::app
