#include "platforms/DynamicLibrary.h"
#include "platforms/Platform.h"

#include <dlfcn.h>

namespace pb::platform {

DynamicLibrary::DynamicLibrary(const std::string& backend, std::initializer_list<const char*> names)
    : backend_(backend) {
    std::string tried;
    for (const char* name : names) {
        // RTLD_LOCAL keeps the library's gl* symbols out of the global namespace, where they
        // could shadow another backend's entry points.
        handle_ = dlopen(name, RTLD_NOW | RTLD_LOCAL);
        if (handle_) {
            soname_ = name;
            return;
        }
        const char* why = dlerror();
        tried += std::string(tried.empty() ? "" : "; ") + (why ? why : name);
    }
    throw PlatformUnavailable(backend + ": cannot load its library (" + tried + ")");
}

void* DynamicLibrary::find(const char* symbol) const {
    return dlsym(handle_, symbol);
}

void* DynamicLibrary::requireAddress(const char* symbol) const {
    void* address = find(symbol);
    if (!address)
        throw PlatformError(backend_ + ": " + soname_ + " lacks the entry point " + symbol);
    return address;
}

} // namespace pb::platform
