// Writes the GBuffer channels; locations come from the channel table (GBufferLayout.cpp).
#include "common_octahedral.glsl"
#include "common_color.glsl"
in vec3 v_normal;
in vec2 v_uv;
layout(location = GBUFFER_LOC_albedo) out vec4 out_albedo;
layout(location = GBUFFER_LOC_normal) out vec4 out_normal;
layout(location = GBUFFER_LOC_emissive) out vec4 out_emissive;
layout(location = GBUFFER_LOC_flags) out vec4 out_flags;
uniform vec4 u_baseColor;
uniform vec3 u_emissive;
uniform int u_hasBaseColorTex;
uniform int u_hasEmissiveTex;
uniform int u_doubleSided;
uniform float u_alphaCutoff;   // < 0: opaque
uniform float u_flags;         // flag bits / 255
uniform sampler2D u_baseColorTex;
uniform sampler2D u_emissiveTex;
void main() {
    vec4 base = u_baseColor;
    if (u_hasBaseColorTex != 0) {
        vec4 t = texture(u_baseColorTex, v_uv); // sRGB8_A8 texture: already linear
        base *= t;
    }
    if (u_alphaCutoff >= 0.0 && base.a < u_alphaCutoff) discard;
    vec3 emissive = u_emissive;
    if (u_hasEmissiveTex != 0) emissive *= texture(u_emissiveTex, v_uv).rgb;
    vec3 n = normalize(v_normal);
    // Double-sided surfaces face the viewer; a zero-length normal from a bad mesh stays finite.
    if (u_doubleSided != 0 && !gl_FrontFacing) n = -n;
    if (!(dot(n, n) > 0.5)) n = vec3(0.0, 1.0, 0.0);
    out_albedo = vec4(base.rgb, 1.0);
    out_normal = vec4(octEncode(n), 0.0, 1.0);
    out_emissive = vec4(emissive, 1.0);
    out_flags = vec4(u_flags, 0.0, 0.0, 1.0);
}
