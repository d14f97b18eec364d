#pragma once
// Programs compiled once per (vertex, fragment, variant defines) and kept for the context's
// lifetime; passes ask for the variant their profile switches select.
#include "gl/Program.h"

#include <map>
#include <memory>

namespace pb::gl {

// Sees every program the cache builds, around the build: what a driver reports while it
// compiles and links (its KHR_debug messages, e.g. Mesa's shader statistics) falls between the
// two calls. `probebench shaders` attributes driver statistics to programs with it.
class ProgramBuildObserver {
public:
    virtual ~ProgramBuildObserver() = default;
    virtual void beforeBuild(const std::string& vertex, const std::string& fragment,
                             const Defines& defines) = 0;
    // Also called when the build threw (then `built` is false and the exception goes on).
    virtual void afterBuild(const std::string& vertex, const std::string& fragment,
                            const Defines& defines, bool built) = 0;
};

class ProgramCache {
public:
    const Program& get(const std::string& vertex, const std::string& fragment,
                       const Defines& defines = {});
    std::size_t size() const { return programs_.size(); }
    void clear() { programs_.clear(); }
    // Null to stop observing. The observer must outlive its registration.
    void setObserver(ProgramBuildObserver* observer) { observer_ = observer; }

private:
    std::map<std::string, std::unique_ptr<Program>> programs_;
    ProgramBuildObserver* observer_ = nullptr;
};

} // namespace pb::gl
