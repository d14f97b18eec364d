#include "passes/DynamicObjects.h"

#include "passes/GBufferLayout.h"

#include <algorithm>
#include <map>

namespace pb::render {

DynamicObjects findDynamicObjects(const scene::Scene& s) {
    DynamicObjects d;
    d.objectOfInstance.assign(s.instances.size(), -1);
    std::map<std::string, int> byName;
    for (size_t i = 0; i < s.instances.size(); ++i) {
        const scene::Instance& inst = s.instances[i];
        if (!inst.dynamic) continue;
        auto [it, added] = byName.emplace(inst.nodeName, int(d.objects.size()));
        if (added) d.objects.push_back({inst.nodeName, {}, {}});
        DynamicObject& o = d.objects[size_t(it->second)];
        o.instances.push_back(int(i));
        d.objectOfInstance[i] = it->second;
        const scene::Bounds& local = s.primitives[size_t(inst.primitive)].localBounds;
        if (local.empty()) continue;
        for (int c = 0; c < 8; ++c) {
            const glm::vec3 p((c & 1) ? local.max.x : local.min.x,
                              (c & 2) ? local.max.y : local.min.y,
                              (c & 4) ? local.max.z : local.min.z);
            o.bounds.extend(glm::vec3(inst.transform * glm::vec4(p, 1.0f)));
        }
    }
    return d;
}

unsigned gbufferFlagBits(const DynamicObjects& d, int instance) {
    const int object = d.objectOfInstance[size_t(instance)];
    if (object < 0) return 0;
    return kFlagDynamic | (unsigned(std::min(object, kMaxShObjects - 1)) << 1);
}

} // namespace pb::render
