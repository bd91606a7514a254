// SPDX-License-Identifier: BSD-3-Clause
// upsample: each pixel's smooth remittance (Jakob & Hanika 2019 sigmoid
// polynomial) fitted under the source light and re-lit spectrally under the
// target; the metamer 3×3 for pixels with no positive channel.
#include <algorithm>

#include <Eigen/LU>

#include "spectral/Parallel.h"
#include "transforms/SpectralMethods.h"
#include "transforms/Upsampler.h"
#include "transforms/detail/MethodFits.h"
#include "transforms/methods/PixelOp.h"

namespace bandlight
{

namespace
{

class Upsample final : public PixelOp
{
public:
    Upsample(const SurfaceRenderer& from, const SurfaceRenderer& to, const Mat3& fallback,
             bool hasPost, const Mat3& post)
        : m_from(from),
          m_to(to),
          m_upsampler(m_from),
          m_fits(UpsampleFits::ForSource(m_from)),
          m_fallback(fallback),
          m_hasPost(hasPost),
          m_post(post)
    {
    }

    Vec3 apply(const Vec3& in) const override
    {
        const Vec3 out = UpsampleRelight(m_upsampler, m_to, m_fallback, in);
        return m_hasPost ? Vec3(m_post * out) : out;
    }

    void apply(Vec3* rgb, size_t count) const override
    {
        // One fit per chromaticity (all exposures of a colour), as the float
        // path shares them.
        UpsampleRendered rendered;
        for (size_t i = 0; i < count; ++i)
        {
            const Vec3 out = UpsampleRelight(*m_fits, m_to, m_fallback, rgb[i], rendered);
            rgb[i] = m_hasPost ? Vec3(m_post * out) : out;
        }
    }

    void applyAfterInput(float* rgb, size_t count, int threads) const override
    {
        auto run = [&](size_t begin, size_t end)
        {
            // Fits are shared (per chromaticity, across targets and threads)
            // and start from the flat grey: a pixel's result depends on
            // nothing but the pixel.
            UpsampleRendered rendered;
            for (size_t i = begin; i < end; ++i)
            {
                float* p = rgb + 3 * i;
                const Vec3 in = GuardPixel(Vec3(p[0], p[1], p[2]));
                Vec3 out = UpsampleRelight(*m_fits, m_to, m_fallback, in, rendered);
                if (m_hasPost)
                {
                    out = m_post * out;
                }
                p[0] = float(out.x());
                p[1] = float(out.y());
                p[2] = float(out.z());
            }
        };
        // Below 1024 pixels a thread costs more than it saves.
        ParallelFor(count, count < 1024 ? 1 : threads, run);
    }

    Mat3 linearPart() const override { return m_fallback; }

private:
    SurfaceRenderer m_from;
    SurfaceRenderer m_to;
    Upsampler m_upsampler;
    /// The fits under `from`, shared with every op from that light.
    std::shared_ptr<UpsampleFits> m_fits;
    Mat3 m_fallback;
    bool m_hasPost;
    Mat3 m_post;
};

}  // namespace

namespace detail
{

std::unique_ptr<PixelOp> UpsampleOp(const Light& from, const Light& to, const MethodSpec& method,
                                    const RgbSpace& working, Observer observer)
{
    const PlateBalance balance = BalanceOf(from, to, method, working, observer);
    const Mat3 fallback = MetamerMatrix(SurfaceRenderer(from.spectrum, working, observer),
                                        SurfaceRenderer(to.spectrum, working, observer));
    auto op = std::make_unique<Upsample>(SurfaceRenderer(from.spectrum, working, observer),
                                         SurfaceRenderer(to.spectrum, working, observer), fallback,
                                         balance.balanced, balance.to);
    op->hasInput = balance.balanced;
    op->input = balance.from.inverse();
    return op;
}

std::shared_ptr<void> UpsampleShared(const Light& from, const RgbSpace& working, Observer observer)
{
    return UpsampleFits::ForSource(SurfaceRenderer(from.spectrum, working, observer));
}

}  // namespace detail

}  // namespace bandlight
