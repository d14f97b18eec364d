// The SH technique's irradiance lookup of ONE probe volume (gi.technique=sh_l1|sh_l2): the
// GLSL port of the CPU reference renderer/probes/sh/ShSampler.cpp (its header lists the steps),
// with one hardware trilinear fetch per 3D texture (renderer/passes/GpuShTextures.h has the
// layout). Needs common_ddgi.glsl first: the volume's frame, fade and bias uniforms
// (u_ddgiCenter, u_ddgiToLocal, u_ddgiHalf, u_ddgiFadeWidth, u_ddgiInvCell, u_ddgiCounts,
// u_ddgiBiasDistance, u_ddgiIrradianceScale) and ddgiLocal / ddgiSafeNormalize are shared, so
// volume choice, nesting and gi.multi_volume=stencil work exactly as for DDGI.
// Variants: GI_TECHNIQUE_SH_L1 | GI_TECHNIQUE_SH_L2, GI_SH_LEAK_NONE | _WEIGHT | _VALIDITY_MASK.
// Arithmetic is highp in every gi.precision (the fetches are few; fp16 would add error that
// the CPU reference does not model).
uniform highp sampler3D u_shCoefficients0; // R: l=0, (1,-1), (1,0), (1,1)
uniform highp sampler3D u_shCoefficients1; // G
uniform highp sampler3D u_shCoefficients2; // B
#ifdef GI_TECHNIQUE_SH_L2
uniform highp sampler3D u_shCoefficients3; // quadratic: R0..R4 G0..G4 B0..B4, 4 a texel
uniform highp sampler3D u_shCoefficients4;
uniform highp sampler3D u_shCoefficients5;
uniform highp sampler3D u_shCoefficients6;
#endif
uniform highp sampler3D u_shValidity; // R8: validity (none) or the cell's valid-corner mask

const float SH_A0 = 3.14159265;
const float SH_A1 = 2.09439510;
const float SH_A2 = 0.78539816;

#ifdef GI_SH_LEAK_VALIDITY_MASK
// ShSampler.cpp nudgeToValid: the least move of the fractions (each kept, 0 or 1) that gives
// every invalid corner weight 0.
vec3 shNudge(vec3 f, int mask) {
    if (mask == 255) return f;
    vec3 best = f;
    float bestMove = 1e30;
    for (int option = 0; option < 27; ++option) {
        vec3 g;
        int o = option;
        for (int a = 0; a < 3; ++a) {
            int m = o - (o / 3) * 3;
            g[a] = m == 0 ? f[a] : float(m - 1);
            o /= 3;
        }
        bool clean = true;
        for (int c = 0; c < 8; ++c) {
            if ((mask & (1 << c)) != 0) continue;
            float w = 1.0;
            for (int a = 0; a < 3; ++a) w *= ((c >> a) & 1) != 0 ? g[a] : 1.0 - g[a];
            if (w != 0.0) clean = false;
        }
        float move = abs(g.x - f.x) + abs(g.y - f.y) + abs(g.z - f.z);
        if (clean && move < bestMove) {
            bestMove = move;
            best = g;
        }
    }
    return best;
}
#endif

// rgb = E * fade (times u_ddgiIrradianceScale, the pre-exposure), a = fade; 0 when nothing
// valid contributes.
vec4 shSample(vec3 pos, vec3 normal, vec3 view) {
    vec3 p = ddgiLocal(pos);
    vec3 n = ddgiSafeNormalize(u_ddgiToLocal * normal, vec3(0.0, 1.0, 0.0));
    vec3 v = ddgiSafeNormalize(u_ddgiToLocal * view, n);
    float fade = ddgiEdgeFade(p);
    if (fade <= 0.0) return vec4(0.0);
    vec3 b = p + (DDGI_BIAS_NORMAL * n + DDGI_BIAS_VIEW * v) * u_ddgiBiasDistance;
    vec3 counts = vec3(u_ddgiCounts);
    vec3 g = clamp((b + u_ddgiHalf) * u_ddgiInvCell, vec3(0.0), counts - 1.0);
#if defined(GI_SH_LEAK_VALIDITY_MASK) || defined(GI_SH_LEAK_WEIGHT)
    vec3 base = min(floor(g), max(counts - 2.0, vec3(0.0)));
    int mask = int(texelFetch(u_shValidity, ivec3(base.x, base.z, base.y), 0).r * 255.0 + 0.5);
    if (mask == 0) return vec4(0.0);
#endif
#ifdef GI_SH_LEAK_VALIDITY_MASK
    g = base + shNudge(g - base, mask);
#endif
#ifdef GI_SH_LEAK_WEIGHT
    // The filtered weight: the valid corners' trilinear weights, summed in float from the
    // cell's mask rather than by a hardware fetch of an R8 weight - llvmpipe filters UNORM8
    // with 8-bit weights and RGBA16F with float ones, and that mismatch put the quotient up to
    // 10% off the reference where the weight is small (GiShCrossCheckTest, measured).
    vec3 f = g - base;
    float w = 0.0;
    for (int c = 0; c < 8; ++c) {
        if ((mask & (1 << c)) == 0) continue;
        float wc = 1.0;
        for (int a = 0; a < 3; ++a) wc *= ((c >> a) & 1) != 0 ? f[a] : 1.0 - f[a];
        w += wc;
    }
#endif
    // Texel centres sit on the probes; texture axes (x, rows z, layers y).
    vec3 uvw = (g.xzy + 0.5) / counts.xzy;
    vec4 cR = texture(u_shCoefficients0, uvw);
    vec4 cG = texture(u_shCoefficients1, uvw);
    vec4 cB = texture(u_shCoefficients2, uvw);
#ifdef GI_TECHNIQUE_SH_L2
    vec4 q0 = texture(u_shCoefficients3, uvw);
    vec4 q1 = texture(u_shCoefficients4, uvw);
    vec4 q2 = texture(u_shCoefficients5, uvw);
    vec4 q3 = texture(u_shCoefficients6, uvw);
#endif
#ifdef GI_SH_LEAK_WEIGHT
    if (!(w > 0.0)) return vec4(0.0);
    float invW = 1.0 / w;
#else
    float invW = 1.0;
#endif
    // ShIrradiance.cpp shBasis, times the cosine lobe per band.
    vec4 l1 = vec4(SH_A0 * 0.282094792, SH_A1 * 0.488602512 * n.y, SH_A1 * 0.488602512 * n.z,
                   SH_A1 * 0.488602512 * n.x);
    vec3 e = vec3(dot(cR, l1), dot(cG, l1), dot(cB, l1));
#ifdef GI_TECHNIQUE_SH_L2
    float y4 = SH_A2 * 1.092548431 * n.x * n.y, y5 = SH_A2 * 1.092548431 * n.y * n.z;
    float y6 = SH_A2 * 0.315391565 * (3.0 * n.z * n.z - 1.0);
    float y7 = SH_A2 * 1.092548431 * n.x * n.z, y8 = SH_A2 * 0.546274215 * (n.x * n.x - n.y * n.y);
    e.r += dot(q0, vec4(y4, y5, y6, y7)) + q1.x * y8;
    e.g += dot(q1.yzw, vec3(y4, y5, y6)) + dot(q2.xy, vec2(y7, y8));
    e.b += dot(q2.zw, vec2(y4, y5)) + dot(q3.xyz, vec3(y6, y7, y8));
#endif
    e = max(e * invW, vec3(0.0));
    return vec4(e * fade * u_ddgiIrradianceScale, fade);
}
