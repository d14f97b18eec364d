#pragma once
// Upsample (gi.upsample, only when gi.resolution is half or quarter): turns the GI apply
// pass's low-resolution target into the full-resolution GI target the lighting reads
// (FrameContext::gi), as its own pass so the benchmark times it as "upsample".
//   bilinear   one hardware-filtered fetch (gi_upsample_bilinear.frag)
//   bilateral  four samples weighted by the full-resolution GBuffer's depth and normals
//   temporal   a full-resolution history (ping-pong) reprojected with the camera matrices,
//              refreshed by per-frame jittered low-resolution samples (gi_upsample_temporal)
// beginFrame runs before the frame's passes: it picks the jitter the apply pass samples with
// (FrameContext::giJitter) and decides whether the history is usable (camera cut rule or an
// explicit resetHistory()).
#include "camera/Reprojection.h"
#include "camera/TemporalSampling.h"
#include "passes/FrameContext.h"
#include "profile/Profile.h"

#include <cstdint>
#include <memory>

namespace pb::render {

camera::CameraState cameraState(const RenderView& view);

class GiUpsamplePass : public Pass {
public:
    static constexpr int kLowUnit = 5; // after the GBuffer's channels and depth
    static constexpr int kHistoryGiUnit = 6;
    static constexpr int kHistoryDistanceUnit = 7;

    explicit GiUpsamplePass(const profile::Profile& profile);
    ~GiUpsamplePass() override;
    const char* name() const override { return "upsample"; }

    // Before the frame's passes: sets frame.giJitter and decides whether this frame reuses the
    // history (temporal only).
    void beginFrame(const RenderView& view, FrameContext& frame);
    void execute(FrameContext& frame) override;

    // The next frame starts a fresh history (a camera cut the application knows about).
    void resetHistory() { resetRequested_ = true; }
    // This frame reprojected the previous one's history (false: first frame, cut, reset, or
    // not temporal).
    bool historyUsed() const { return historyValid_; }
    // Frames since the history was last reset (0 on the reset frame itself).
    std::uint64_t framesSinceReset() const { return frameIndex_; }
    const gl::Texture* output() const;
    std::size_t bytes() const; // GPU memory of the output (and history) targets

private:
    struct Target;

    profile::GiUpsample mode_;
    int divisor_;
    camera::CameraCutRule cutRule_;
    std::unique_ptr<Target> targets_[2]; // [current] is written; temporal reads [1 - current]
    int current_ = 0;
    camera::CameraState previous_, now_;
    bool havePrevious_ = false, resetRequested_ = false, historyValid_ = false;
    std::uint64_t frameIndex_ = 0;
};

} // namespace pb::render
