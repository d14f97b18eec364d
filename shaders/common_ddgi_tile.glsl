// A probe's tile (column, row, layer) from its state texel's w: |w| = code + 1 with
// code = column | row << columnBits | layer << (columnBits + rowBits); w > 0 valid, < 0
// invalid, 0 absent (no tile). renderer/probes/store/SparseLayout.h (TileCode) encodes it, exactly
// (the state texture is RGBA32F: integers to 2^24); GpuProbes::bindVolume sets the widths.
// Shifts and masks only: the integer division a slot index needs is emulated per lane on
// llvmpipe and by a sequence of ALU instructions on GPUs. One decode for common_ddgi.glsl's
// sparse path (DDGI_SPARSE_TILES) and the probe debug spheres, never a copy.
uniform ivec2 u_ddgiTileBits; // (column bits, row bits) of the bound volume's code

// The fields' masks and shifts: (column mask, row shift, row mask, layer shift).
ivec4 ddgiTileFields;

// Call once before the probe loops (ddgiSample does). A uniform read inside the loops costs
// llvmpipe a per-lane load at each use (about 6 M instructions per use at the gate's view,
// studies/README.md "Probe placement"); values computed up front stay in registers.
void ddgiInitTileFields() {
    ivec2 b = u_ddgiTileBits;
    ddgiTileFields = ivec4((1 << b.x) - 1, b.x, (1 << b.y) - 1, b.x + b.y);
}

// `magnitude` = |w| of a probe that owns a tile (an integer >= 1).
ivec3 ddgiTile(float magnitude) {
    int code = (int(magnitude) - 1) & 0x7FFFFF; // without kNoVisibilityFlag (bit 23)
    return ivec3(code & ddgiTileFields.x, (code >> ddgiTileFields.y) & ddgiTileFields.z,
                 code >> ddgiTileFields.w);
}
