#include "probes/bc6h/Bc6hFit.h"

#include <algorithm>
#include <cmath>

namespace pb::probes::bc6h {
namespace {

int subsetOf(int partition, int regions, int texel) {
    return regions == 2 ? (kPartitions[partition] >> texel) & 1 : 0;
}

int anchorOf(int partition, int subset) {
    return subset == 0 ? 0 : kAnchor2[partition];
}

// Difference b - a taken modulo 2^epb into [-2^(epb-1), 2^(epb-1)): the decoder adds deltas
// with wrap-around, so this representative is the one with a chance to fit the delta bits.
int wrapDiff(int diff, int epb) {
    const int range = 1 << epb;
    diff &= range - 1;
    return diff >= range / 2 ? diff - range : diff;
}

bool deltaFits(int diff, int bits) {
    return diff >= -(1 << (bits - 1)) && diff < (1 << (bits - 1));
}

bool deltasFit(const ModeInfo& info, const int ep[4][3]) {
    if (!info.transformed) return true;
    for (int e = 1; e < 2 * info.regions; ++e)
        for (int c = 0; c < 3; ++c)
            if (!deltaFits(wrapDiff(ep[e][c] - ep[0][c], info.epb), info.delta[c])) return false;
    return true;
}

// The epb-bit value whose unquantised value is nearest to q.
int quantizeValue(float q, int epb) {
    const int maxValue = (1 << epb) - 1;
    const int guess =
        std::clamp(static_cast<int>(q * static_cast<float>(1 << epb) / 65536.0f), 0, maxValue);
    int best = guess;
    float bestDist = std::fabs(static_cast<float>(unquantize(guess, epb)) - q);
    for (int x = std::max(guess - 1, 0); x <= std::min(guess + 1, maxValue); ++x) {
        const float d = std::fabs(static_cast<float>(unquantize(x, epb)) - q);
        if (d < bestDist) {
            bestDist = d;
            best = x;
        }
    }
    return best;
}

// Builds the decoded half-bit palette of one subset.
void palette(const ModeInfo& info, const int e0[3], const int e1[3], float out[16][3]) {
    const int n = info.regions == 2 ? 8 : 16;
    const int* weights = info.regions == 2 ? kWeights3 : kWeights4;
    int u0[3], u1[3];
    for (int c = 0; c < 3; ++c) {
        u0[c] = unquantize(e0[c], info.epb);
        u1[c] = unquantize(e1[c], info.epb);
    }
    for (int j = 0; j < n; ++j)
        for (int c = 0; c < 3; ++c)
            out[j][c] = static_cast<float>(finishUnsigned(interpolate(u0[c], u1[c], weights[j])));
}

float texelError(const float h[3], const float p[3]) {
    const float dr = p[0] - h[0], dg = p[1] - h[1], db = p[2] - h[2];
    return dr * dr + dg * dg + db * db;
}

// The palette entries lie on a line in half-bit space (up to the +-1 rounding of the integer
// interpolation), so the nearest entry is the one nearest in projection onto that line: only
// the projected index and its neighbours need checking, not all 8 or 16 entries.
struct PaletteLine {
    float origin[3];
    float dir[3]; // scaled so that projection * dir gives 0..count-1
    int count = 0;
};

PaletteLine paletteLine(const float pal[16][3], int count) {
    PaletteLine l;
    l.count = count;
    float len2 = 0.0f;
    for (int c = 0; c < 3; ++c) {
        l.origin[c] = pal[0][c];
        l.dir[c] = pal[count - 1][c] - pal[0][c];
        len2 += l.dir[c] * l.dir[c];
    }
    const float scale = len2 > 0.0f ? static_cast<float>(count - 1) / len2 : 0.0f;
    for (int c = 0; c < 3; ++c)
        l.dir[c] *= scale;
    return l;
}

// Best index in [0, limit) for one texel; returns its error.
float bestIndex(const float h[3], const float pal[16][3], const PaletteLine& line, int limit,
                int& index) {
    float t = 0.0f;
    for (int c = 0; c < 3; ++c)
        t += (h[c] - line.origin[c]) * line.dir[c];
    const int guess = std::clamp(static_cast<int>(t + 0.5f), 0, limit - 1);
    const int lo = std::max(guess - 1, 0), hi = std::min(guess + 1, limit - 1);
    float best = texelError(h, pal[lo]);
    index = lo;
    for (int j = lo + 1; j <= hi; ++j) {
        const float e = texelError(h, pal[j]);
        if (e < best) {
            best = e;
            index = j;
        }
    }
    return best;
}

void swapEndpoints(Encoding& enc, int subset, int regions, int indexCount) {
    for (int c = 0; c < 3; ++c)
        std::swap(enc.ep[2 * subset][c], enc.ep[2 * subset + 1][c]);
    for (int t = 0; t < 16; ++t)
        if (subsetOf(enc.partition, regions, t) == subset)
            enc.index[t] = static_cast<std::uint8_t>(indexCount - 1 - enc.index[t]);
}

} // namespace

float halfBitsContinuous(float v) {
    if (v < 6.103515625e-05f) return v * 16777216.0f; // subnormal halves: 2^-24 per step
    int e = 0;
    const float m = std::frexp(v, &e); // v = m * 2^e, m in [0.5, 1)
    return static_cast<float>((e + 14) * 1024) + (2.0f * m - 1.0f) * 1024.0f;
}

void prepareTarget(const float* texels, BlockTarget& out) {
    for (int i = 0; i < 16; ++i) {
        for (int c = 0; c < 3; ++c) {
            const float h = halfBitsContinuous(clampSource(texels[i * 3 + c]));
            out.h[i][c] = h;
            // finishUnsigned floors i * 31 / 64, so aim at the middle of the interval of
            // interpolated values that land on the wanted half.
            out.q[i][c] = std::min((h + 0.5f) * (64.0f / 31.0f), kMaxInterp);
        }
    }
}

bool deltasRepresentable(const Encoding& enc) {
    return deltasFit(modeInfo(enc.mode), enc.ep);
}

void quantizeAbsolute(const Lines& lines, int epb, int regions, int out[4][3]) {
    for (int e = 0; e < 2 * regions; ++e)
        for (int c = 0; c < 3; ++c)
            out[e][c] = quantizeValue(lines.e[e][c], epb);
}

bool quantizeEndpoints(const Lines& lines, Encoding& enc) {
    const ModeInfo& info = modeInfo(enc.mode);
    const int endpoints = 2 * info.regions;
    const int mask = (1 << info.epb) - 1;
    for (int e = 0; e < endpoints; ++e)
        for (int c = 0; c < 3; ++c)
            enc.ep[e][c] = quantizeValue(lines.e[e][c], info.epb);
    if (!info.transformed) return true;
    bool exact = true;
    for (int e = 1; e < endpoints; ++e) {
        for (int c = 0; c < 3; ++c) {
            const int base = enc.ep[0][c];
            const int lo = -(1 << (info.delta[c] - 1)), hi = (1 << (info.delta[c] - 1)) - 1;
            const int wrapped = wrapDiff(enc.ep[e][c] - base, info.epb);
            if (deltaFits(wrapped, info.delta[c])) continue;
            exact = false;
            // Out of range: the nearest representable value is either a clamped plain delta
            // or a clamped wrapped one; take whichever lands closer to the wanted value.
            const int plain = std::clamp(enc.ep[e][c] - base, lo, hi) + base;
            const int viaWrap = (base + std::clamp(wrapped, lo, hi)) & mask;
            const float want = lines.e[e][c];
            const float dPlain = std::fabs(static_cast<float>(unquantize(plain, info.epb)) - want);
            const float dWrap = std::fabs(static_cast<float>(unquantize(viaWrap, info.epb)) - want);
            enc.ep[e][c] = (plain >= 0 && plain <= mask && dPlain <= dWrap) ? plain : viaWrap;
        }
    }
    return exact;
}

float evaluate(const BlockTarget& t, Encoding& enc) {
    const ModeInfo& info = modeInfo(enc.mode);
    const int regions = info.regions;
    const int count = regions == 2 ? 8 : 16;
    float pal[2][16][3];
    PaletteLine lines[2];
    for (int s = 0; s < regions; ++s) {
        palette(info, enc.ep[2 * s], enc.ep[2 * s + 1], pal[s]);
        lines[s] = paletteLine(pal[s], count);
    }

    float errors[16];
    float total = 0.0f;
    for (int i = 0; i < 16; ++i) {
        int index = 0;
        const int s = subsetOf(enc.partition, regions, i);
        errors[i] = bestIndex(t.h[i], pal[s], lines[s], count, index);
        enc.index[i] = static_cast<std::uint8_t>(index);
        total += errors[i];
    }

    // Anchor texels have an implicit zero high index bit.
    for (int s = 0; s < regions; ++s) {
        const int anchor = anchorOf(enc.partition, s);
        if (enc.index[anchor] < count / 2) continue;
        // Reversing a subset gives identical values (the weights are symmetric) but moves the
        // delta base when it is subset 0, which the delta bits may not be able to express.
        swapEndpoints(enc, s, regions, count);
        if (s == 1 || deltasFit(info, enc.ep)) continue;
        swapEndpoints(enc, s, regions, count);
        int index = 0;
        const float e = bestIndex(t.h[anchor], pal[s], lines[s], count / 2, index);
        enc.index[anchor] = static_cast<std::uint8_t>(index);
        total += e - errors[anchor];
    }
    enc.error = total;
    return total;
}

void refine(const BlockTarget& t, Encoding& enc, int iterations) {
    const ModeInfo& info = modeInfo(enc.mode);
    const int regions = info.regions;
    const int* weights = regions == 2 ? kWeights3 : kWeights4;
    for (int it = 0; it < iterations; ++it) {
        Lines lines;
        for (int s = 0; s < regions; ++s) {
            float aa = 0, ab = 0, bb = 0, ax[3] = {}, bx[3] = {};
            for (int i = 0; i < 16; ++i) {
                if (subsetOf(enc.partition, regions, i) != s) continue;
                const float w = static_cast<float>(weights[enc.index[i]]) / 64.0f;
                const float v = 1.0f - w;
                aa += v * v;
                ab += v * w;
                bb += w * w;
                for (int c = 0; c < 3; ++c) {
                    ax[c] += v * t.q[i][c];
                    bx[c] += w * t.q[i][c];
                }
            }
            const float det = aa * bb - ab * ab;
            for (int c = 0; c < 3; ++c) {
                float a = static_cast<float>(unquantize(enc.ep[2 * s][c], info.epb));
                float b = static_cast<float>(unquantize(enc.ep[2 * s + 1][c], info.epb));
                if (det > 1e-6f) {
                    a = (ax[c] * bb - bx[c] * ab) / det;
                    b = (bx[c] * aa - ax[c] * ab) / det;
                }
                lines.e[2 * s][c] = std::clamp(a, 0.0f, kMaxInterp);
                lines.e[2 * s + 1][c] = std::clamp(b, 0.0f, kMaxInterp);
            }
        }
        Encoding trial = enc;
        quantizeEndpoints(lines, trial);
        if (evaluate(t, trial) < enc.error)
            enc = trial;
        else
            break;
    }
}

void perturb(const BlockTarget& t, Encoding& enc, int passes) {
    const ModeInfo& info = modeInfo(enc.mode);
    const int maxValue = (1 << info.epb) - 1;
    for (int pass = 0; pass < passes; ++pass) {
        bool improved = false;
        for (int e = 0; e < 2 * info.regions; ++e) {
            for (int c = 0; c < 3; ++c) {
                for (int step : {-1, 1}) {
                    Encoding trial = enc;
                    const int v = trial.ep[e][c] + step;
                    if (v < 0 || v > maxValue) continue;
                    trial.ep[e][c] = v;
                    if (!deltasFit(info, trial.ep)) continue;
                    if (evaluate(t, trial) < enc.error) {
                        enc = trial;
                        improved = true;
                    }
                }
            }
        }
        if (!improved) break;
    }
}

void pack(const Encoding& enc, std::uint8_t out[16]) {
    const ModeInfo& info = modeInfo(enc.mode);
    int fields[13] = {};
    for (int e = 0; e < 2 * info.regions; ++e) {
        for (int c = 0; c < 3; ++c) {
            int v = enc.ep[e][c];
            if (info.transformed && e > 0)
                v = wrapDiff(v - enc.ep[0][c], info.epb) & ((1 << info.delta[c]) - 1);
            fields[e * 3 + c] = v;
        }
    }
    fields[kPartitionField] = enc.partition;

    Bits128 bits;
    const FieldBit* layout = headerLayout(enc.mode);
    const int header = headerBits(info.regions);
    for (int pos = 0; pos < header; ++pos) {
        const FieldBit fb = layout[pos];
        const int value = fb.field == kModeField ? info.code : fields[fb.field];
        bits.setBit(pos, (value >> fb.bit) & 1);
    }
    const int indexBits = info.regions == 2 ? 3 : 4;
    const int anchor2 = info.regions == 2 ? kAnchor2[enc.partition] : -1;
    int pos = header;
    for (int i = 0; i < 16; ++i) {
        const int n = (i == 0 || i == anchor2) ? indexBits - 1 : indexBits;
        bits.setBits(pos, n, enc.index[i]);
        pos += n;
    }
    bits.store(out);
}

} // namespace pb::probes::bc6h
