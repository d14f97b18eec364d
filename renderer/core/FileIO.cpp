#include "core/FileIO.h"

#include "core/Error.h"

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace pb {

void writeFileAtomic(const std::string& path, const void* bytes, std::size_t size) {
    namespace fs = std::filesystem;
    fs::path target(path);
    if (target.has_parent_path() && !fs::is_directory(target.parent_path()))
        throw fileError(path, "folder does not exist");
    std::string tmp = path + ".tmp." + std::to_string(::getpid());
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) throw fileError(path, "cannot open for writing");
        out.write(static_cast<const char*>(bytes), std::streamsize(size));
        out.flush();
        if (!out) {
            out.close();
            fs::remove(tmp);
            throw fileError(path, "write failed (disk full?)");
        }
    }
    std::error_code ec;
    fs::rename(tmp, target, ec);
    if (ec) {
        fs::remove(tmp);
        throw fileError(path, "cannot rename temporary file: " + ec.message());
    }
}

std::vector<unsigned char> readFileBytes(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw fileError(path, "file not found");
    if (std::filesystem::is_directory(path, ec)) throw fileError(path, "is a folder, not a file");
    // A FIFO or a device would block the open or never end (a glTF buffer URI can name any
    // path): only regular files are read.
    if (!std::filesystem::is_regular_file(path, ec))
        throw fileError(path, "not a regular file (a device, FIFO or socket)");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw fileError(path, "cannot open for reading");
    in.seekg(0, std::ios::end);
    std::streamoff size = in.tellg();
    in.seekg(0);
    std::vector<unsigned char> data(size_t(size > 0 ? size : 0));
    if (size > 0) in.read(reinterpret_cast<char*>(data.data()), size);
    if (!in) throw fileError(path, "read failed");
    return data;
}

} // namespace pb
