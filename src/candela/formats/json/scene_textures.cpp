// The `textures` part of a scene file, and material parameters that may be textures: a constant,
// `{"texture": NAME}`, or a texture object written in place. Textures go into Scene::textures
// (textures/texture_set.h), inputs before the textures that read them; image files are listed in
// Scene::texture_files once per file and colorspace, and read by load_texture_images.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "candela/formats/json/scene_sections.h"
#include "candela/formats/json/scene_spectra.h"
#include "candela/spectrum/spectrum_rgb.h"

namespace candela {

namespace fs = std::filesystem;

namespace {

constexpr std::array<std::string_view, 7> kTextureTypes = {"constant", "image",  "checkerboard", "scale",
                                                           "mix",      "bilerp", "directionmix"};
constexpr std::array<std::string_view, 3> kColorspaceNames = {"srgb", "linear", "gamma"};
constexpr std::array<std::string_view, 3> kWrapNames = {"repeat", "clamp", "black"};
constexpr std::array<std::string_view, 2> kFilterNames = {"bilinear", "point"};

// The closed range [lo, hi] a texture's values are clamped to for a parameter within `bounds`
// (an open end moves to the next float inside).
std::pair<float, float> clamp_range(const Bounds& bounds) {
    float lo = float(bounds.lo), hi = float(bounds.hi);
    if (bounds.lo_open) lo = std::nextafter(lo, kUnbounded);
    if (bounds.hi_open) hi = std::nextafter(hi, -kUnbounded);
    return {lo, hi};
}

// The constant a textured parameter carries for the material's load-time BSDF (material.h),
// which a textured material does not use to shade: 1, moved into the parameter's range.
float placeholder(float lo, float hi) { return std::min(std::max(1.0f, lo), hi); }

// Reads textures and texture parameters. A reference by name finds a texture of the `textures`
// section: while that section is read, by reading it first (depth first, so forward references
// work and a cycle is found as a name already being read); from a material, among those read.
class TextureReader {
  public:
    explicit TextureReader(Scene& scene) : scene_(scene) {}

    // The textures section: every texture in file order (those already read as inputs skipped).
    void read_section(JsonCursor section) {
        for (auto& [name, cursor] : section.members()) section_.push_back({name, cursor});
        for (size_t i = 0; i < section_.size(); ++i)
            if (section_[i].state == Named::kUnread) read_named(i, section_[i].cursor);
    }

    // A colour: RGB, a texture, or a spectrum (scene_spectra.h). A value bounded by 1 is a
    // reflectance and becomes a spectrum in spectral mode by the albedo form, any other by the
    // unbounded form (pbrt-v4's SpectrumType). A spectrum is kept for spectral mode and reduced
    // to RGB (spectrum_rgb.h) for RGB mode.
    ColorParam color_param(JsonCursor c, const Bounds& bounds) {
        const SpectrumForm form = bounds.hi <= 1.0 ? SpectrumForm::kAlbedo : SpectrumForm::kUnbounded;
        if (!c.is_object()) return ColorParam{c.colour(bounds), kNoTexture, -kUnbounded, kUnbounded, form};
        if (std::optional<DenseSpectrum> s = read_spectrum(c, scene_.file.parent_path())) {
            for (float v : s->v)
                if (!(double(v) >= bounds.lo && double(v) <= bounds.hi))
                    c.fail(fmt::format("a spectrum value {} is outside this colour's range [{}, {}]", v, bounds.lo,
                                       bounds.hi));
            ColorParam p{reflectance_rgb(*s), kNoTexture, -kUnbounded, kUnbounded, form};
            p.spectrum = scene_.textures.add_spectrum(*s);
            return p;
        }
        const auto [lo, hi] = clamp_range(bounds);
        return ColorParam{Rgb(placeholder(lo, hi)), texture_of(c), lo, hi, form};
    }

    FloatParam float_param(JsonCursor c, const Bounds& bounds) {
        if (!c.is_object()) return FloatParam{c.number_f(bounds)};
        const auto [lo, hi] = clamp_range(bounds);
        return FloatParam{placeholder(lo, hi), texture_of(c), lo, hi};
    }

    // A normal map: a file name is an image texture of that file, read linearly (a normal map
    // is data, not colour), repeating and bilinear, as pbrt-v4's `normalmap`; anything else is a
    // colour parameter in [0, 1].
    ColorParam normal_map_param(JsonCursor c) {
        if (!c.is_string()) return color_param(std::move(c), Bounds::closed(0, 1));
        ImageTexture t;
        t.image = image_index(c, std::nullopt, TextureColorspace::kLinear);
        const uint32_t index = scene_.textures.add(t);
        scene_.texture_names.emplace_back();
        return ColorParam{Rgb(1.0f), index, 0.0f, 1.0f};
    }

  private:
    struct Named {
        std::string name;
        JsonCursor cursor;
        enum State { kUnread, kReading, kDone } state = kUnread;
        uint32_t index = 0;
    };

    // The texture an object parameter gives: a reference {"texture": NAME} or a texture object.
    uint32_t texture_of(JsonCursor& c) {
        if (auto name = c.get("texture")) {
            c.reject_unknown_keys();
            return resolve(*name);
        }
        return read_texture(c);
    }

    uint32_t resolve(const JsonCursor& name_cursor) {
        const std::string name = name_cursor.string();
        for (size_t i = 0; i < section_.size(); ++i) {
            if (section_[i].name != name) continue;
            if (section_[i].state == Named::kDone) return section_[i].index;
            if (section_[i].state == Named::kReading) {
                std::string cycle;
                for (const std::string& open : reading_) cycle += json_quoted(open) + " -> ";
                name_cursor.fail(fmt::format("textures form a cycle: {}{}", cycle, json_quoted(name)));
            }
            return read_named(i, section_[i].cursor);
        }
        const auto found = std::find(scene_.texture_names.begin(), scene_.texture_names.end(), name);
        if (!name.empty() && found != scene_.texture_names.end())
            return uint32_t(found - scene_.texture_names.begin());
        std::vector<std::string> defined;
        for (const Named& n : section_) defined.push_back(n.name);
        for (const std::string& n : scene_.texture_names)
            if (!n.empty()) defined.push_back(n);
        name_cursor.fail(fmt::format("unknown texture {}; {}", json_quoted(name),
                                     defined.empty() ? "the scene defines no textures"
                                                     : "defined textures: " + join(defined)));
    }

    uint32_t read_named(size_t i, JsonCursor c) {
        section_[i].state = Named::kReading;
        reading_.push_back(section_[i].name);
        const uint32_t index = read_texture(c);
        reading_.pop_back();
        section_[i].state = Named::kDone;
        section_[i].index = index;
        scene_.texture_names[index] = section_[i].name;
        return index;
    }

    // A texture object (with "type"), its inputs read first.
    uint32_t read_texture(JsonCursor& c) {
        // Bounds the reader's recursion as well as evaluation's (names read depth first recurse
        // before any texture is added).
        if (++open_ > kMaxTextureDepth) fail_too_deep(c);
        c.expect_object();
        const std::string_view type = c.require("type").choice("texture type", kTextureTypes);
        Texture texture = read_kind(c, type);
        c.reject_unknown_keys();
        const uint32_t index = scene_.textures.add(texture);
        scene_.texture_names.emplace_back();
        if (scene_.textures.depth(index) > kMaxTextureDepth) fail_too_deep(c);
        --open_;
        return index;
    }

    [[noreturn]] static void fail_too_deep(const JsonCursor& c) {
        c.fail(fmt::format("textures nest more than {} deep (a texture, its input, the input's "
                           "input ...); expected a shallower chain of textures",
                           kMaxTextureDepth));
    }

    Texture read_kind(JsonCursor& c, std::string_view type) {
        if (type == "constant") {
            ConstantTexture t;
            if (auto v = c.get("value")) t.value = v->colour(Bounds{});
            return t;
        }
        if (type == "image") return read_image_texture(c);
        if (type == "checkerboard") return read_checkerboard(c);
        if (type == "bilerp") {
            // pbrt-v4's defaults: 0 along s = 0 ... v00 0, v01 1, v10 0, v11 1.
            BilerpTexture t;
            if (auto v = c.get("v00")) t.v00 = v->colour(Bounds{});
            if (auto v = c.get("v01")) t.v01 = v->colour(Bounds{});
            if (auto v = c.get("v10")) t.v10 = v->colour(Bounds{});
            if (auto v = c.get("v11")) t.v11 = v->colour(Bounds{});
            t.uv = read_uv_transform(c);
            return t;
        }
        if (type == "directionmix") {
            DirectionMixTexture t;
            if (auto v = c.get("tex1")) t.tex1 = color_param(*v, Bounds{});
            if (auto v = c.get("tex2")) t.tex2 = color_param(*v, Bounds{});
            if (auto v = c.get("dir")) {
                const Vec3d d = v->vec3();
                if (!(length(d) > 0.0)) v->fail("expected a direction, got the zero vector");
                t.dir = Vec3f(normalize(d));
            }
            return t;
        }
        if (type == "scale") {
            ScaleTexture t;
            if (auto v = c.get("tex")) t.tex = color_param(*v, Bounds{});
            if (auto v = c.get("scale")) t.scale = float_param(*v, Bounds{});
            return t;
        }
        MixTexture t;
        if (auto v = c.get("tex1")) t.tex1 = color_param(*v, Bounds{});
        if (auto v = c.get("tex2")) t.tex2 = color_param(*v, Bounds{});
        if (auto v = c.get("amount")) t.amount = float_param(*v, Bounds::closed(0, 1));
        return t;
    }

    // `checkerboard`: over the surface's (s, t) (`dimension` 2, pbrt-v4's default), or with
    // `dimension` 3 over the hit point in the texture's own space: `transform` (default none)
    // takes that space into the world, as pbrt-v4's CTM at its Texture directive does.
    Texture read_checkerboard(JsonCursor& c) {
        ColorParam color0{Rgb(1.0f)}, color1{Rgb(0.0f)};
        if (auto v = c.get("color0")) color0 = color_param(*v, Bounds{});
        if (auto v = c.get("color1")) color1 = color_param(*v, Bounds{});
        int dimension = 2;
        if (auto v = c.get("dimension")) {
            dimension = int(v->integer(Bounds::closed(2, 3)));
        }
        if (dimension == 2) {
            if (auto v = c.get("transform")) v->fail("a transform is for a checkerboard of dimension 3");
            CheckerboardTexture t;
            t.color0 = color0;
            t.color1 = color1;
            t.uv = read_uv_transform(c);
            return t;
        }
        for (std::string_view key : {"uv_scale", "uv_offset"})
            if (auto v = c.get(key))
                v->fail(fmt::format("\"{}\" is for a checkerboard of dimension 2 (over uv); dimension 3 takes "
                                    "\"transform\"",
                                    key));
        Checkerboard3DTexture t;
        t.color0 = color0;
        t.color1 = color1;
        if (auto v = c.get("transform")) {
            const Transform::Matrix m = read_transform(*v).inverse().matrix();
            auto row = [&](int i) { return Vec3f(Vec3d(m[i][0], m[i][1], m[i][2])); };
            t.space = TextureSpace{row(0), row(1), row(2), Vec3f(Vec3d(m[0][3], m[1][3], m[2][3]))};
        }
        return t;
    }

    static UvTransform read_uv_transform(JsonCursor& c) {
        UvTransform uv;
        if (auto v = c.get("uv_scale")) uv.scale = read_pair(*v, "an array of 2 numbers [su, sv]");
        if (auto v = c.get("uv_offset")) uv.offset = read_pair(*v, "an array of 2 numbers [du, dv]");
        return uv;
    }

    static Vec2f read_pair(const JsonCursor& c, std::string_view what) {
        std::vector<JsonCursor> xy = c.elements(2, what);
        return Vec2f(xy[0].number_f(), xy[1].number_f());
    }

    ImageTexture read_image_texture(JsonCursor& c) {
        ImageTexture t;
        JsonCursor file = c.require("file");
        std::optional<JsonCursor> colorspace = c.get("colorspace");
        std::optional<JsonCursor> gamma_key = c.get("gamma");
        if (auto v = c.get("wrap")) {
            const std::string_view wrap = v->choice("wrap mode", kWrapNames);
            t.wrap = wrap == "clamp" ? TextureWrap::kClamp : wrap == "black" ? TextureWrap::kBlack : TextureWrap::kRepeat;
        }
        if (auto v = c.get("filter"))
            t.filter = v->choice("texture filter", kFilterNames) == "point" ? TextureFilter::kPoint
                                                                           : TextureFilter::kBilinear;
        t.uv = read_uv_transform(c);
        if (auto v = c.get("scale")) t.scale = v->number_f(Bounds::at_least(0));
        if (auto v = c.get("invert")) t.invert = v->boolean();
        t.image = image_index(file, colorspace, TextureColorspace::kSrgb, gamma_key);
        return t;
    }

    // The index in scene.textures' images of the file `file` names in `colorspace` (default
    // `fallback`; float formats are linear), listing it in scene.texture_files when new.
    // `gamma_key`: the exponent of colorspace "gamma" (pbrt-v4's encoding "gamma G"), needed
    // there and nowhere else.
    uint32_t image_index(const JsonCursor& file, const std::optional<JsonCursor>& colorspace_key,
                         TextureColorspace fallback = TextureColorspace::kSrgb,
                         const std::optional<JsonCursor>& gamma_key = std::nullopt) {
        const fs::path path = referenced_file(file, scene_.file.parent_path(), "texture image");
        if (!is_texture_file_extension(path))
            file.fail(fmt::format("expected an image file ({}), got {}", texture_file_extensions(),
                                  json_quoted(file.string())));
        TextureColorspace colorspace = fallback;
        if (colorspace_key) {
            const std::string_view name = colorspace_key->choice("colorspace", kColorspaceNames);
            colorspace = name == "linear"  ? TextureColorspace::kLinear
                         : name == "gamma" ? TextureColorspace::kGamma
                                           : TextureColorspace::kSrgb;
        }
        float gamma = 1.0f;
        if (colorspace == TextureColorspace::kGamma) {
            if (!gamma_key) colorspace_key->fail("colorspace \"gamma\" needs a \"gamma\" exponent, e.g. \"gamma\": 2.2");
            gamma = gamma_key->number_f(Bounds::above(0));
        } else if (gamma_key) {
            gamma_key->fail("\"gamma\" is the exponent of \"colorspace\": \"gamma\"");
        }
        if (is_float_texture_file(path)) {
            if (colorspace_key && colorspace != TextureColorspace::kLinear)
                colorspace_key->fail(fmt::format("{} holds linear values; {} applies only to "
                                                 "8- and 16-bit images (.png, .jpg, .jpeg, .tga, .bmp)",
                                                 json_quoted(file.string()), json_quoted(colorspace_key->string())));
            colorspace = TextureColorspace::kLinear;
            gamma = 1.0f;
        }
        std::error_code ec;
        fs::path canonical = fs::canonical(path, ec);
        if (ec) file.fail(fmt::format("cannot resolve texture image {}: {}", json_quoted(file.string()), ec.message()));
        for (size_t i = 0; i < scene_.texture_files.size(); ++i) {
            const TextureFile& known = scene_.texture_files[i];
            if (known.canonical == canonical && known.colorspace == colorspace && known.gamma == gamma)
                return uint32_t(i);
        }
        scene_.texture_files.push_back({path, std::move(canonical), colorspace, gamma, file.string(), file.pointer()});
        return scene_.textures.add_image(TextureImage{});
    }

    static std::string join(const std::vector<std::string>& names) {
        std::string list;
        for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
        return list;
    }

    Scene& scene_;
    std::vector<Named> section_;        // the textures section, while it is read
    std::vector<std::string> reading_;  // the names being read, outermost first
    int open_ = 0;                      // texture objects being read, nested
};

}  // namespace

void read_textures(JsonCursor textures, Scene& scene) { TextureReader(scene).read_section(std::move(textures)); }

ColorParam read_color_param(const JsonCursor& c, Scene& scene, const Bounds& bounds) {
    return TextureReader(scene).color_param(c, bounds);
}

FloatParam read_float_param(const JsonCursor& c, Scene& scene, const Bounds& bounds) {
    return TextureReader(scene).float_param(c, bounds);
}

ColorParam read_normal_map_param(const JsonCursor& c, Scene& scene) { return TextureReader(scene).normal_map_param(c); }

void load_texture_images(Scene& scene, const JsonDocument& document, MemoryBudget& budget) {
    for (size_t i = 0; i < scene.texture_files.size(); ++i) {
        const TextureFile& file = scene.texture_files[i];
        auto charge = [&](uint64_t bytes, uint64_t transient, int width, int height) {
            if (auto refused = budget.charge(bytes,
                                             fmt::format("texture image {} ({}x{})", json_quoted(file.name),
                                                         width, height),
                                             transient))
                document.fail(file.pointer, *refused);
        };
        std::optional<TextureFileHeader> header =
            load_referenced(document, file.pointer, [&] { return read_texture_file_header(file.path); });
        // 8- and 16-bit files are charged from their header, before they are decoded; float
        // formats once read (their readers check the size against the file first, image_io.h).
        if (header)
            charge(texture_memory_bytes(header->width, header->height, header->channels, header->bytes_per_channel),
                   texture_loading_memory_bytes(header->file_bytes, header->width, header->height,
                                                header->channels, header->bytes_per_channel),
                   header->width, header->height);
        TextureImage image =
            load_referenced(document, file.pointer, [&] { return read_texture_file(file.path, file.colorspace, file.gamma); });
        if (!header) charge(image.memory_bytes(), 0, image.width, image.height);
        scene.textures.set_image(uint32_t(i), std::move(image));
    }
}

}  // namespace candela
