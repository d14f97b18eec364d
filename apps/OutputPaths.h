#pragma once
// Output paths that say what they get: a missing parent folder is an error unless the user
// asked for it (`--mkdir`; a typo in a folder name used to create a tree of folders), and a
// file name's extension must be the format written (`--out x.jpg` used to get PNG bytes).
#include <string>
#include <vector>

namespace pb::app {

// Throws `option: 'path' ...` when `path`'s extension (case-insensitive) is not one of
// `extensions` (".png"), naming `format`; or when its parent folder is missing and not `mkdir`.
// Checked before anything is rendered, so a refusal costs nothing and writes nothing.
void checkOutputFile(const std::string& option, const std::string& path,
                     const std::vector<std::string>& extensions, const std::string& format,
                     bool mkdir);

// A folder of outputs (--dump-gbuffer): created itself, but its parent must exist unless `mkdir`.
void checkOutputFolder(const std::string& option, const std::string& path, bool mkdir);

// Creates `path`'s parent folder (only reached with --mkdir or when it exists already).
void makeParentFolder(const std::string& path);

// The one rule of every command that writes a file (bake, bench, truth, render): checked before
// any work, a missing parent folder is an error naming it, unless `mkdir` (--mkdir), which
// creates it here.
void prepareOutputParent(const std::string& option, const std::string& path, bool mkdir);

} // namespace pb::app
