#pragma once
// The scene's textures, referenced by index from material parameters (texture_param.h), and the
// images they read. A texture's inputs always have smaller indices than the texture itself (the
// loader adds them first), so the textures form a DAG, and its nesting depth is bounded
// (kMaxTextureDepth) so that evaluation's recursion is too.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "candela/core/check.h"
#include "candela/core/platform.h"
#include "candela/core/variant.h"
#include "candela/spectrum/dense_spectrum.h"
#include "candela/textures/texture_context.h"
#include "candela/textures/texture_image.h"
#include "candela/textures/texture_kinds.h"
#include "candela/textures/texture_param.h"

namespace candela {

using Texture = Variant<ConstantTexture, ImageTexture, CheckerboardTexture, ScaleTexture, MixTexture, BilerpTexture,
                        DirectionMixTexture, Checkerboard3DTexture>;

// The most textures a chain of inputs may hold (a texture with no inputs has depth 1).
inline constexpr int kMaxTextureDepth = 16;

class TextureSet {
  public:
    CANDELA_HD bool empty() const { return textures_.empty(); }
    CANDELA_HD size_t size() const { return textures_.size(); }
    CANDELA_HD size_t image_count() const { return images_.size(); }

    // The parameter's value at ctx: its constant, or its texture's value there clamped to the
    // parameter's range. A texture index this set does not hold gives the constant (make_material
    // builds a textured material's load-time BSDF with an empty set).
    CANDELA_HD float eval(const FloatParam& p, const TextureContext& ctx) const {
        if (!holds(p.texture)) return p.value;
        const float v = number(p.texture, ctx);
        return v < p.lo ? p.lo : (v > p.hi ? p.hi : v);
    }
    // In spectral mode (ctx.lambda set) the colour at the path's wavelengths: the parameter's
    // tabulated spectrum, its constant's uplift, or its texture's RGB uplifted here.
    CANDELA_HD Color eval(const ColorParam& p, const TextureContext& ctx) const {
        if (ctx.lambda) {
            // The common case inline: a constant's uplift prepared at load.
            if (p.spectrum == kNoSpectrum && !holds(p.texture)) return p.spectral.eval(*ctx.lambda);
            return eval_spectral(p, *ctx.lambda, ctx);
        }
        return from_rgb(rgb(p, ctx));
    }
    [[gnu::noinline]] CANDELA_HD Color eval_spectral(const ColorParam& p, const Color& lambda,
                                                     const TextureContext& ctx) const {
        if (p.spectrum != kNoSpectrum) return spectra_[p.spectrum].eval(lambda);
        if (!holds(p.texture)) return p.spectral.eval(lambda);
        return uplift(rgb(p, ctx), p.form).eval(lambda);
    }
    // The parameter's RGB value at ctx (texture inputs are RGB in both modes).
    CANDELA_HD Rgb rgb(const ColorParam& p, const TextureContext& ctx) const {
        if (!holds(p.texture)) return p.value;
        return clamp_channels(color(p.texture, ctx), p.lo, p.hi);
    }
    // The parameter's three channels as a vector, for data that is not a colour (a normal map's
    // x, y, z), clamped as eval's. Colours are RGB today; the spectral mode must read the RGB of
    // the texture here, never a spectrum.
    CANDELA_HD Vec3f eval_vector(const ColorParam& p, const TextureContext& ctx) const {
        const Rgb c = rgb(p, ctx);
        return Vec3f(c.r, c.g, c.b);
    }
    // A colour parameter read as a number (a texture input that gives a number: `mix` of numbers).
    CANDELA_HD float number(const ColorParam& p, const TextureContext& ctx) const {
        if (!holds(p.texture)) return channel_average(p.value);
        const float v = number(p.texture, ctx);
        return v < p.lo ? p.lo : (v > p.hi ? p.hi : v);
    }

    // Texture i's colour and number at ctx.
    CANDELA_HD Rgb color(uint32_t i, const TextureContext& ctx) const {
        return visit([&](const auto& t) { return t.color(*this, ctx); }, textures_[i]);
    }
    CANDELA_HD float number(uint32_t i, const TextureContext& ctx) const {
        return visit([&](const auto& t) { return t.number(*this, ctx); }, textures_[i]);
    }

    CANDELA_HD const Texture& texture(uint32_t i) const { return textures_[i]; }
    // Tabulated spectrum i (named, listed, read from a file or a blackbody), for spectral mode.
    CANDELA_HD const DenseSpectrum& spectrum(uint32_t i) const { return spectra_[i]; }
    size_t spectrum_count() const { return spectra_.size(); }
    uint32_t add_spectrum(const DenseSpectrum& s) {
        spectra_.push_back(s);
        return uint32_t(spectra_.size() - 1);
    }
    CANDELA_HD const TextureImage& image(uint32_t i) const { return images_[i]; }
    // Texture i's nesting depth: 1 plus the largest depth of its inputs.
    int depth(uint32_t i) const { return depths_[i]; }

    // --- building (the scene loader)
    // Adds `t`, whose inputs must already be in the set; returns its index.
    uint32_t add(const Texture& t) {
        int d = 0;
        visit([&](const auto& kind) {
            kind.for_each_input([&](uint32_t input) {
                CANDELA_CHECK(input < textures_.size());
                d = std::max(d, depths_[input]);
            });
        }, t);
        textures_.push_back(t);
        depths_.push_back(d + 1);
        return uint32_t(textures_.size() - 1);
    }
    // Adds an image for ImageTexture::image to index; returns its index.
    uint32_t add_image(TextureImage image) {
        images_.push_back(std::move(image));
        return uint32_t(images_.size() - 1);
    }
    // Replaces image i (the loader reserves indices while reading the scene file and reads the
    // files afterwards).
    void set_image(uint32_t i, TextureImage image) { images_[i] = std::move(image); }

    // The bytes the images' texels take.
    uint64_t image_memory_bytes() const {
        uint64_t bytes = 0;
        for (const TextureImage& image : images_) bytes += image.memory_bytes();
        return bytes;
    }

  private:
    CANDELA_HD bool holds(uint32_t i) const { return i < textures_.size(); }

    std::vector<Texture> textures_;
    std::vector<int> depths_;  // parallel to textures_
    std::vector<TextureImage> images_;
    std::vector<DenseSpectrum> spectra_;
};

static_assert(TextureKind<ConstantTexture, TextureSet>);
static_assert(TextureKind<ImageTexture, TextureSet>);
static_assert(TextureKind<CheckerboardTexture, TextureSet>);
static_assert(TextureKind<ScaleTexture, TextureSet>);
static_assert(TextureKind<MixTexture, TextureSet>);
static_assert(TextureKind<BilerpTexture, TextureSet>);
static_assert(TextureKind<DirectionMixTexture, TextureSet>);
static_assert(TextureKind<Checkerboard3DTexture, TextureSet>);

}  // namespace candela
