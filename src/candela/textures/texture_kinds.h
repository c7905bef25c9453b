#pragma once
// The kinds of texture, as values: each gives a colour and a number at a shading point. A texture
// used for a colour parameter is evaluated with color(), for a number parameter with number()
// (pbrt-v4 has a Float and a Spectrum version of each texture; here one value serves both).
//
// A texture's inputs are parameters (texture_param.h): constants, or other textures of the same
// TextureSet by index, so textures nest. Each kind is a template over the set that holds it, so
// it can evaluate its inputs without this header depending on texture_set.h.
#include <cmath>
#include <concepts>
#include <cstdint>

#include "candela/math/color.h"
#include "candela/textures/texture_context.h"
#include "candela/textures/texture_image.h"
#include "candela/textures/texture_param.h"
#include "candela/textures/uv_transform.h"

namespace candela {

template <class T, class Set>
concept TextureKind = requires(const T& t, const Set& set, const TextureContext& ctx) {
    // The value as a colour and as a number at ctx.
    { t.color(set, ctx) } -> std::same_as<Rgb>;
    { t.number(set, ctx) } -> std::same_as<float>;
    // The textures it reads (indices into the set), each passed to f; for the loader's checks.
    t.for_each_input([](uint32_t) {});
};

// `constant`: one value everywhere; read as a number, the average of its channels.
struct ConstantTexture {
    Rgb value;

    template <class Set>
    CANDELA_HD Rgb color(const Set&, const TextureContext&) const { return value; }
    template <class Set>
    CANDELA_HD float number(const Set&, const TextureContext&) const { return channel_average(value); }
    template <class F>
    void for_each_input(F&&) const {}
};

// `image`: an image of the set (texture_image.h) at the transformed uv, times `scale`, inverted
// to 1 - value when `invert` (pbrt-v4's imagemap: a colour is then clamped at 0, a number
// inverted to max(0, 1 - value)). As a number it reads one channel or the average
// (TextureImage::number).
struct ImageTexture {
    uint32_t image = 0;  // index into the set's images
    UvTransform uv;
    TextureWrap wrap = TextureWrap::kRepeat;
    TextureFilter filter = TextureFilter::kBilinear;
    float scale = 1.0f;
    bool invert = false;

    template <class Set>
    CANDELA_HD Rgb color(const Set& set, const TextureContext& ctx) const {
        Rgb v = set.image(image).lookup(uv.apply(ctx.uv), wrap, filter).rgb * scale;
        if (invert) v = Rgb(1.0f) - v;
        return clamp_channels(v, 0.0f, kUnbounded);
    }
    template <class Set>
    CANDELA_HD float number(const Set& set, const TextureContext& ctx) const {
        const TextureImage& img = set.image(image);
        const float v = img.number(img.lookup(uv.apply(ctx.uv), wrap, filter)) * scale;
        return invert ? (v < 1.0f ? 1.0f - v : 0.0f) : v;
    }
    template <class F>
    void for_each_input(F&&) const {}
};

// What the 2D and 3D checkerboards share: their two colours (pbrt-v4's tex1 and tex2, each maybe
// a texture, evaluated only where it shows), chosen by the derived board's odd().
template <class Board>
struct CheckerColors {
    ColorParam color0{Rgb(1.0f)};
    ColorParam color1{Rgb(0.0f)};

    template <class Set>
    CANDELA_HD Rgb color(const Set& set, const TextureContext& ctx) const {
        return set.rgb(board().odd(ctx) ? color1 : color0, ctx);
    }
    template <class Set>
    CANDELA_HD float number(const Set& set, const TextureContext& ctx) const {
        return set.number(board().odd(ctx) ? color1 : color0, ctx);
    }
    template <class F>
    void for_each_input(F&& f) const {
        if (color0.is_textured()) f(color0.texture);
        if (color1.is_textured()) f(color1.texture);
    }

  private:
    CANDELA_HD const Board& board() const { return static_cast<const Board&>(*this); }
};

// `checkerboard`: color0 where floor(s) + floor(t) is even, color1 where it is odd, (s, t) the
// transformed uv (pbrt-v4's checkerboard without its antialiasing filter; color0 and color1 are
// its tex1 and tex2). Each colour may itself be a texture, evaluated only where it shows.
struct CheckerboardTexture : CheckerColors<CheckerboardTexture> {
    UvTransform uv;

    // Whether (s, t) lies on a color1 square. In float: every float beyond 2^24 is an even
    // integer, so the parity of the sum stays defined however far out the point is.
    CANDELA_HD bool odd(const TextureContext& ctx) const {
        const Vec2f st = uv.apply(ctx.uv);
        return std::fmod(std::floor(st.x) + std::floor(st.y), 2.0f) != 0.0f;
    }

};

// `scale`: `tex` times the number `scale` (pbrt-v4's scale texture).
struct ScaleTexture {
    ColorParam tex{Rgb(1.0f)};
    FloatParam scale{1.0f};

    template <class Set>
    CANDELA_HD Rgb color(const Set& set, const TextureContext& ctx) const {
        return set.rgb(tex, ctx) * set.eval(scale, ctx);
    }
    template <class Set>
    CANDELA_HD float number(const Set& set, const TextureContext& ctx) const {
        return set.number(tex, ctx) * set.eval(scale, ctx);
    }
    template <class F>
    void for_each_input(F&& f) const {
        if (tex.is_textured()) f(tex.texture);
        if (scale.is_textured()) f(scale.texture);
    }
};

// `mix`: (1 - amount) tex1 + amount tex2, the number `amount` in [0, 1] (pbrt-v4's mix; as
// there, an input whose weight is 0 is not evaluated).
struct MixTexture {
    ColorParam tex1{Rgb(0.0f)};
    ColorParam tex2{Rgb(1.0f)};
    FloatParam amount{0.5f, kNoTexture, 0.0f, 1.0f};

    template <class Set>
    CANDELA_HD Rgb color(const Set& set, const TextureContext& ctx) const {
        const float a = set.eval(amount, ctx);
        Rgb c(0.0f);
        if (a != 1.0f) c += set.rgb(tex1, ctx) * (1.0f - a);
        if (a != 0.0f) c += set.rgb(tex2, ctx) * a;
        return c;
    }
    template <class Set>
    CANDELA_HD float number(const Set& set, const TextureContext& ctx) const {
        const float a = set.eval(amount, ctx);
        float v = 0.0f;
        if (a != 1.0f) v += set.number(tex1, ctx) * (1.0f - a);
        if (a != 0.0f) v += set.number(tex2, ctx) * a;
        return v;
    }
    template <class F>
    void for_each_input(F&& f) const {
        if (tex1.is_textured()) f(tex1.texture);
        if (tex2.is_textured()) f(tex2.texture);
        if (amount.is_textured()) f(amount.texture);
    }
};


// `bilerp`: the bilinear interpolation of four colours over the transformed (s, t): v00 at
// (0, 0), v10 at (1, 0), v01 at (0, 1), v11 at (1, 1) (pbrt-v4's bilerp; outside the unit square
// it extrapolates, as there).
struct BilerpTexture {
    Rgb v00{0.0f};
    Rgb v01{1.0f};
    Rgb v10{0.0f};
    Rgb v11{1.0f};
    UvTransform uv;

    template <class Set>
    CANDELA_HD Rgb color(const Set&, const TextureContext& ctx) const {
        const Vec2f st = uv.apply(ctx.uv);
        const float s = st.x, t = st.y;
        return v00 * ((1.0f - s) * (1.0f - t)) + v10 * (s * (1.0f - t)) + v01 * ((1.0f - s) * t) + v11 * (s * t);
    }
    template <class Set>
    CANDELA_HD float number(const Set& set, const TextureContext& ctx) const {
        return channel_average(color(set, ctx));
    }
    template <class F>
    void for_each_input(F&&) const {}
};

// `directionmix`: w tex1 + (1 - w) tex2 with w = |n . dir|, n the surface's geometric normal and
// `dir` a unit vector in world space (pbrt-v4's directionmix, whose `dir` is in the texture's
// space: the importer turns it into the world's). As in pbrt-v4, an input whose weight is 0 is
// not evaluated.
struct DirectionMixTexture {
    ColorParam tex1{Rgb(0.0f)};
    ColorParam tex2{Rgb(1.0f)};
    Vec3f dir{0.0f, 1.0f, 0.0f};

    CANDELA_HD float weight(const TextureContext& ctx) const { return std::abs(dot(ctx.n, dir)); }

    template <class Set>
    CANDELA_HD Rgb color(const Set& set, const TextureContext& ctx) const {
        const float w = weight(ctx);
        Rgb c(0.0f);
        if (w != 0.0f) c += set.rgb(tex1, ctx) * w;
        if (w != 1.0f) c += set.rgb(tex2, ctx) * (1.0f - w);
        return c;
    }
    template <class Set>
    CANDELA_HD float number(const Set& set, const TextureContext& ctx) const {
        const float w = weight(ctx);
        float v = 0.0f;
        if (w != 0.0f) v += set.number(tex1, ctx) * w;
        if (w != 1.0f) v += set.number(tex2, ctx) * (1.0f - w);
        return v;
    }
    template <class F>
    void for_each_input(F&& f) const {
        if (tex1.is_textured()) f(tex1.texture);
        if (tex2.is_textured()) f(tex2.texture);
    }
};

// A point's coordinates in a solid texture's own space, p' = M p + offset (the inverse of the
// scene file's `transform` of the texture, made at load, in float).
struct TextureSpace {
    Vec3f row0{1.0f, 0.0f, 0.0f};
    Vec3f row1{0.0f, 1.0f, 0.0f};
    Vec3f row2{0.0f, 0.0f, 1.0f};
    Vec3f offset{0.0f, 0.0f, 0.0f};

    CANDELA_HD Vec3f apply(const Vec3f& p) const {
        return Vec3f(dot(row0, p) + offset.x, dot(row1, p) + offset.y, dot(row2, p) + offset.z);
    }
};

// `checkerboard` with `dimension` 3: a solid checkerboard of unit cubes in the texture's space,
// color0 where floor(x) + floor(y) + floor(z) is even, color1 where it is odd (pbrt-v4's 3D
// checkerboard over its PointTransformMapping, without the antialiasing filter).
struct Checkerboard3DTexture : CheckerColors<Checkerboard3DTexture> {
    TextureSpace space;

    // Whether the point lies in a color1 cube (the sum in float, as CheckerboardTexture::odd).
    CANDELA_HD bool odd(const TextureContext& ctx) const {
        const Vec3f p = space.apply(ctx.p);
        return std::fmod(std::floor(p.x) + std::floor(p.y) + std::floor(p.z), 2.0f) != 0.0f;
    }

};

}  // namespace candela
