#pragma once
// Programs compiled once per (vertex, fragment, variant defines) and kept for the context's
// lifetime; passes ask for the variant their profile switches select.
#include "gl/Program.h"

#include <map>
#include <memory>

namespace pb::gl {

class ProgramCache {
public:
    const Program& get(const std::string& vertex, const std::string& fragment,
                       const Defines& defines = {});
    std::size_t size() const { return programs_.size(); }
    void clear() { programs_.clear(); }

private:
    std::map<std::string, std::unique_ptr<Program>> programs_;
};

} // namespace pb::gl
