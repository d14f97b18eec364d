#pragma once
// A shared library opened at run time (dlopen). The GL backends load libEGL / libOSMesa this way
// so that one binary links no GL library at all (see README.md).
#include <initializer_list>
#include <string>

namespace pb::platform {

class DynamicLibrary {
public:
    // Opens the first of `names` that loads. Throws PlatformUnavailable naming the backend and
    // every name tried. The library is never closed: Mesa's drivers and LLVM keep process-wide
    // state that does not survive being unloaded and loaded again.
    DynamicLibrary(const std::string& backend, std::initializer_list<const char*> names);

    const std::string& soname() const { return soname_; }

    // The symbol's address, or nullptr when the library lacks it.
    void* find(const char* symbol) const;

    // The symbol as a function pointer; throws PlatformError when the library lacks it.
    template <class Fn> Fn require(const char* symbol) const {
        return reinterpret_cast<Fn>(requireAddress(symbol));
    }

private:
    void* requireAddress(const char* symbol) const;

    std::string backend_;
    std::string soname_;
    void* handle_ = nullptr;
};

} // namespace pb::platform
