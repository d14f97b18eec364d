#include "gl/ProgramCache.h"

namespace pb::gl {

const Program& ProgramCache::get(const std::string& vertex, const std::string& fragment,
                                 const Defines& defines) {
    std::string key = vertex + "|" + fragment + "|" + definesKey(defines);
    auto it = programs_.find(key);
    if (it == programs_.end())
        it = programs_.emplace(key, std::make_unique<Program>(vertex, fragment, defines)).first;
    return *it->second;
}

} // namespace pb::gl
