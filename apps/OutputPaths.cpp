#include "OutputPaths.h"

#include "core/Error.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace fs = std::filesystem;

namespace pb::app {
namespace {

void requireParent(const std::string& option, const std::string& path, bool mkdir) {
    const fs::path parent = fs::path(path).parent_path();
    if (parent.empty() || mkdir) return;
    std::error_code ec;
    if (fs::is_directory(parent, ec)) return;
    throw Error(option + ": '" + printable(path) + "': folder '" + printable(parent.string()) +
                "' does not exist (--mkdir creates it)");
}

} // namespace

void checkOutputFile(const std::string& option, const std::string& path,
                     const std::vector<std::string>& extensions, const std::string& format,
                     bool mkdir) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (std::find(extensions.begin(), extensions.end(), ext) == extensions.end()) {
        std::string names;
        for (const auto& e : extensions)
            names += (names.empty() ? "" : " or ") + e;
        throw Error(option + ": '" + printable(path) + "': writes " + format +
                    ", so the name must end in " + names +
                    (ext.empty() ? "" : " (not " + printable(ext) + ")"));
    }
    requireParent(option, path, mkdir);
}

void checkOutputFolder(const std::string& option, const std::string& path, bool mkdir) {
    fs::path folder(path);
    if (!folder.has_filename()) folder = folder.parent_path(); // "gb/" names the folder gb
    requireParent(option, folder.string(), mkdir);
}

void prepareOutputParent(const std::string& option, const std::string& path, bool mkdir) {
    requireParent(option, path, mkdir);
    if (mkdir) makeParentFolder(path);
}

void makeParentFolder(const std::string& path) {
    const fs::path parent = fs::path(path).parent_path();
    if (parent.empty()) return;
    std::error_code ec;
    fs::create_directories(parent, ec);
    if (ec) throw fileError(path, "cannot create its folder: " + ec.message());
}

} // namespace pb::app
