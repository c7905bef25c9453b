// The spectrum forms of a colour value, and pbrt-v4's .spd files: text of whitespace-separated
// numbers, alternately a wavelength in nm and a value, with '#' starting a comment to the end of
// the line (pbrt-v4's ReadFloatFile and PiecewiseLinearSpectrum::Read).
#include "candela/formats/json/scene_spectra.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "candela/formats/json/scene_sections.h"
#include "candela/spectrum/blackbody.h"
#include "candela/spectrum/named_spectra.h"
#include "candela/spectrum/spectrum_rgb.h"

namespace candela {

namespace {

constexpr std::array<std::string_view, 3> kSpectrumKeys = {"spectrum", "spectrum_file", "blackbody"};

// At least two pairs: a spectrum of one value is a grey, which the colour's number form gives.
constexpr size_t kMinPairs = 2;

std::string nm(double lambda) { return fmt::format("{} nm", lambda); }

// {"spectrum": [nm, value, nm, value, ...]}
DenseSpectrum read_pairs(const JsonCursor& list) {
    const std::vector<JsonCursor> e = list.elements();
    if (e.size() < 2 * kMinPairs || e.size() % 2 != 0)
        list.fail_expected("an array of (nm, value) pairs: an even number of at least 4 numbers");
    std::vector<float> pairs(e.size());
    for (size_t i = 0; i < e.size(); i += 2) {
        pairs[i] = e[i].number_f(Bounds::above(0));
        if (i > 0 && pairs[i] <= pairs[i - 2])
            e[i].fail(fmt::format("wavelength {} is not above the one before it, {}; wavelengths must "
                                  "increase",
                                  nm(pairs[i]), nm(pairs[i - 2])));
        pairs[i + 1] = e[i + 1].number_f();
    }
    return dense_from_pairs(pairs);
}

// {"spectrum": "name"} or {"spectrum": [...]}
DenseSpectrum read_spectrum_value(const JsonCursor& v) {
    if (v.is_string()) return *named_spectrum(v.choice("spectrum", named_spectrum_names()));
    if (v.is_array()) return read_pairs(v);
    v.fail_expected("a spectrum name or an array of (nm, value) pairs");
}

class SpdReader {
  public:
    explicit SpdReader(std::filesystem::path path) : path_(std::move(path)), name_(path_.string()) {}

    DenseSpectrum read() {
        const std::string text = read_text();
        std::vector<float> pairs;
        int line = 1, last_line = 1;
        for (size_t i = 0; i < text.size();) {
            const char ch = text[i];
            if (ch == '\n') {
                ++line;
                ++i;
            } else if (ch == '#') {
                while (i < text.size() && text[i] != '\n') ++i;
            } else if (std::isspace(static_cast<unsigned char>(ch))) {
                ++i;
            } else {
                size_t end = i;
                while (end < text.size() && !std::isspace(static_cast<unsigned char>(text[end])) &&
                       text[end] != '#')
                    ++end;
                pairs.push_back(number(std::string_view(text).substr(i, end - i), line, pairs));
                last_line = line;
                i = end;
            }
        }
        if (pairs.size() % 2 != 0)
            fail(last_line, fmt::format("{} numbers, an odd count: a wavelength without its value",
                                        pairs.size()));
        if (pairs.size() < 2 * kMinPairs)
            fail(last_line, fmt::format("{} (nm, value) pairs; a spectrum file needs at least {}",
                                        pairs.size() / 2, kMinPairs));
        return dense_from_pairs(pairs);
    }

  private:
    [[noreturn]] void fail(int line, std::string message) const {
        throw SceneError(SourceLocation{name_, line, 0, {}}, std::move(message));
    }

    std::string read_text() const {
        std::ifstream in(path_, std::ios::binary);
        if (!in) fail(0, fmt::format("cannot open spectrum file: {}", std::strerror(errno)));
        std::ostringstream text;
        text << in.rdbuf();
        return text.str();
    }

    // The number `word` at `line`: a wavelength (> 0, above the one before it) when `pairs` so
    // far is even, else a value.
    float number(std::string_view word, int line, const std::vector<float>& pairs) const {
        std::string_view digits = word;
        if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);  // from_chars takes no '+'
        double v = 0.0;
        const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
        if (ec != std::errc() || end != digits.data() + digits.size() || !std::isfinite(v) ||
            std::abs(v) > double(FLT_MAX))
            fail(line, fmt::format("expected a number, got \"{}\"", word));
        const auto f = float(v);
        if (pairs.size() % 2 == 0) {
            if (!(f > 0.0f)) fail(line, fmt::format("expected a wavelength > 0 nm, got {}", word));
            if (!pairs.empty() && f <= pairs[pairs.size() - 2])
                fail(line, fmt::format("wavelength {} is not above the one before it, {}; wavelengths "
                                       "must increase",
                                       nm(f), nm(pairs[pairs.size() - 2])));
        }
        return f;
    }

    std::filesystem::path path_;
    std::string name_;
};

}  // namespace

std::optional<DenseSpectrum> read_spectrum(const JsonCursor& c, const std::filesystem::path& scene_dir) {
    if (!c.is_object()) return std::nullopt;
    const std::vector<std::string> keys = c.keys();
    std::vector<std::string_view> given;
    for (std::string_view k : kSpectrumKeys)
        if (std::find(keys.begin(), keys.end(), k) != keys.end()) given.push_back(k);
    if (given.empty()) return std::nullopt;
    if (given.size() > 1)
        c.document().fail_at_key(c.pointer(), given[1],
                                 fmt::format("a spectrum is one of \"spectrum\", \"spectrum_file\" and "
                                             "\"blackbody\"; this object also has {}",
                                             json_quoted(given[0])));
    JsonCursor o = c;
    std::optional<DenseSpectrum> s;
    if (auto v = o.get("spectrum")) {
        s = read_spectrum_value(*v);
    } else if (auto f = o.get("spectrum_file")) {
        const std::filesystem::path path = referenced_file(*f, scene_dir, "spectrum");
        s = load_referenced(*f, [&] { return SpdReader(path).read(); });
    } else {
        s = blackbody_spectrum(o.require("blackbody").number_f(Bounds::above(0)));
    }
    o.reject_unknown_keys();
    return s;
}

std::optional<LightSpectrum> read_light_spectrum(const JsonCursor& c, const std::filesystem::path& scene_dir) {
    std::optional<DenseSpectrum> s = read_spectrum(c, scene_dir);
    if (!s) return std::nullopt;
    for (float v : s->v)
        if (!(v >= 0.0f)) c.fail(fmt::format("a light's spectrum must be >= 0 at every wavelength, got {}", v));
    LightSpectrum light;
    const double y = spectrum_to_xyz(*s).y;
    if (!(y > 0.0)) return light;
    light.normalized = *s;
    light.normalized *= float(1.0 / y);
    const Rgb rgb = emission_rgb(*s);
    // Its luminance, a positive sum of the channels, is 1: one channel at least stays above 0.
    light.rgb = Rgb(std::max(rgb.r, 0.0f), std::max(rgb.g, 0.0f), std::max(rgb.b, 0.0f));
    return light;
}

}  // namespace candela
