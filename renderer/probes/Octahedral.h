#pragma once
// Octahedral mapping of unit directions to the square [-1,1]^2, and the texel convention of
// the probe tiles. This is the convention the GLSL port must reproduce bit for bit in spirit
// (same formulas, same branch on y < 0); README.md "Octahedral convention" is the spec.
//
// Directions are in the VOLUME's local frame, whose +Y is "up": the upper hemisphere (y >= 0)
// fills the inner diamond |u|+|v| <= 1 with +Y at the centre (0,0); the lower hemisphere is
// folded into the four corner triangles, -Y at the four corners (+-1,+-1).
//   encode: (u,v) = (x,z) / (|x|+|y|+|z|); if y < 0: (u,v) = ((1-|v|)*s(u), (1-|u|)*s(v))
//   decode: (x,y,z) = (u, 1-|u|-|v|, v);  if y < 0: (x,z) = ((1-|v|)*s(u), (1-|u|)*s(v));
//           normalise.     s(a) = a >= 0 ? +1 : -1
// u runs along the texture's x (columns), v along its y (rows, row 0 first in memory).
#include <cmath>
#include <glm/glm.hpp>

namespace pb::probes {

// dir need not be normalised (must not be zero). Always inlined: the sampler calls these
// 9 times per lookup.
[[gnu::always_inline]] inline glm::vec2 octEncode(const glm::vec3& d) {
    const float l1 = std::abs(d.x) + std::abs(d.y) + std::abs(d.z);
    float u = d.x / l1, v = d.z / l1;
    if (d.y < 0.0f) {
        const float fu = (1.0f - std::abs(v)) * (u >= 0.0f ? 1.0f : -1.0f);
        const float fv = (1.0f - std::abs(u)) * (v >= 0.0f ? 1.0f : -1.0f);
        u = fu;
        v = fv;
    }
    return {u, v};
}
glm::vec3 octDecode(const glm::vec2& uv); // unit vector

// Texel (i, j) of an interior of `interior` x `interior` texels has its CENTRE at
// u = (2i+1)/interior - 1, v = (2j+1)/interior - 1 (some centres lie on the equator fold
// |u|+|v| = 1, where both hemispheres agree: decode gives y = 0 there).
glm::vec2 octTexelCentreUv(int i, int j, int interior);
glm::vec3 octTexelDirection(int i, int j, int interior);

// Continuous position of `dir` inside a tile, in texels, measured from the tile's first
// INTERIOR texel's left/top edge: in [0, interior]. Add the 1-texel border and the tile origin
// to get texture coordinates (see ProbeLayout.h).
[[gnu::always_inline]] inline glm::vec2 octInteriorCoord(const glm::vec3& dir, int interior) {
    return (octEncode(dir) * 0.5f + 0.5f) * float(interior);
}

// Fills the 1-texel border of one tile of (interior+2)^2 texels from the mirrored interior
// edge so bilinear filtering wraps the octahedron seamlessly:
//   top row    (x, 0)        = (interior+1-x, 1)          bottom row (x, n+1) = (n+1-x, n)
//   left col   (0, y)        = (1, n+1-y)                 right col  (n+1, y) = (n, n+1-y)
//   corners    (0,0)=(n,n)   (n+1,0)=(1,n)   (0,n+1)=(n,1)   (n+1,n+1)=(1,1)     n = interior
// `tile` points at the tile's texel (0,0); rowPitch is in texels; channels floats per texel.
void fillOctahedralBorder(float* tile, int rowPitch, int channels, int interior);

} // namespace pb::probes
