#include "gl/ProgramCache.h"

namespace pb::gl {

const Program& ProgramCache::get(const std::string& vertex, const std::string& fragment,
                                 const Defines& defines) {
    std::string key = vertex + "|" + fragment + "|" + definesKey(defines);
    auto it = programs_.find(key);
    if (it != programs_.end()) return *it->second;
    if (observer_) observer_->beforeBuild(vertex, fragment, defines);
    std::unique_ptr<Program> program;
    try {
        program = std::make_unique<Program>(vertex, fragment, defines);
    } catch (...) {
        if (observer_) observer_->afterBuild(vertex, fragment, defines, false);
        throw;
    }
    if (observer_) observer_->afterBuild(vertex, fragment, defines, true);
    return *programs_.emplace(key, std::move(program)).first->second;
}

} // namespace pb::gl
