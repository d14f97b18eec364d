#include "passes/GpuTechnique.h"

#include "passes/GpuTechniqueDdgi.h"
#include "passes/GpuTechniqueSh.h"

namespace pb::render {

// The one dispatch on gi.technique on the GPU side: a new technique adds its case here.
std::unique_ptr<GpuTechnique> makeGpuTechnique(profile::GiTechnique technique,
                                               profile::GiShLeak shLeak) {
    switch (technique) {
    case profile::GiTechnique::ShL1:
    case profile::GiTechnique::ShL2:
        return std::make_unique<GpuTechniqueSh>(technique, shLeak);
    case profile::GiTechnique::Ddgi:
        break;
    }
    return std::make_unique<GpuTechniqueDdgi>();
}

} // namespace pb::render
