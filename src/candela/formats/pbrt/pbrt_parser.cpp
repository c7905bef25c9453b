#include "candela/formats/pbrt/pbrt_parser.h"

#include <array>
#include <string>

#include "candela/formats/pbrt/pbrt_directives.h"
#include "candela/formats/pbrt/pbrt_parameter_reader.h"
#include "candela/formats/pbrt/pbrt_token_stream.h"

namespace candela::pbrt {

namespace {

// Reads directives one after the other and hands each to the target: a loop, never recursion,
// so that a million nested AttributeBegin cost no stack (the target keeps the nesting).
class Parser {
  public:
    Parser(Target& target, const ParseOptions& options) : target_(target), tokens_(options) {}
    TokenStream& tokens() { return tokens_; }

    void run() {
        while (tokens_.next(word_)) {
            if (word_.kind != Token::Kind::Word)
                fail(word_.location(), "expected a directive, got " + describe_token(word_));
            const auto directive = find_directive(word_.text);
            if (!directive) fail(word_.location(), "unknown directive \"" + word_.text + "\"");
            dispatch(*directive, word_.location());
        }
        target_.end_of_files();
    }

  private:
    void dispatch(Directive d, const Location& at);

    // The next token, which must exist; `what` says what the directive expected.
    Token& argument(const Location& at, const std::string& what) {
        if (!tokens_.next(argument_)) fail(at, word_.text + ": expected " + what + ", got the end of the file");
        return argument_;
    }
    std::string string_argument(const Location& at, const char* what) {
        const Token& t = argument(at, std::string(what) + " as a quoted string");
        if (t.kind != Token::Kind::String)
            fail(t.location(), word_.text + ": expected " + what + " as a quoted string, got " + describe_token(t));
        return t.text;
    }
    double number_argument(const Location& at) {
        const Token& t = argument(at, "a number");
        if (t.kind != Token::Kind::Word)
            fail(t.location(), word_.text + ": expected a number, got " + describe_token(t));
        return parse_number(t, word_.text);
    }
    template <size_t N>
    std::array<double, N> numbers(const Location& at) {
        std::array<double, N> v{};
        for (double& x : v) x = number_argument(at);
        return v;
    }
    // Transform and ConcatTransform: 16 numbers, in brackets as pbrt-v4 writes them (or without).
    std::array<double, 16> matrix(const Location& at) {
        const bool bracketed = tokens_.peek() && tokens_.peek()->kind == Token::Kind::Open;
        if (bracketed) tokens_.next(argument_);
        const Location open = bracketed ? argument_.location() : at;
        std::array<double, 16> m{};
        for (size_t i = 0; i < m.size(); ++i) {
            if (bracketed && tokens_.peek() && tokens_.peek()->kind == Token::Kind::Close)
                fail(open, word_.text + ": expected 16 numbers, got " + std::to_string(i));
            m[i] = number_argument(at);
        }
        if (bracketed) {
            const Token& t = argument(at, "]");
            if (t.kind != Token::Kind::Close)
                fail(t.location(), word_.text + ": expected ] after 16 numbers, got " + describe_token(t));
        }
        return m;
    }
    std::string name_then(const Location& at, const char* what, ParameterList& params) {
        std::string name = string_argument(at, what);
        params = read_parameters(tokens_);
        return name;
    }

    Target& target_;
    TokenStream tokens_;
    Token word_;      // the directive
    Token argument_;  // its latest argument
    bool warned_transform_begin_ = false;
};

void Parser::dispatch(Directive d, const Location& at) {
    ParameterList params;
    switch (d) {
        case Directive::Identity: target_.identity(at); return;
        case Directive::Translate: {
            const auto v = numbers<3>(at);
            target_.translate(v[0], v[1], v[2], at);
            return;
        }
        case Directive::Scale: {
            const auto v = numbers<3>(at);
            target_.scale(v[0], v[1], v[2], at);
            return;
        }
        case Directive::Rotate: {
            const auto v = numbers<4>(at);
            target_.rotate(v[0], v[1], v[2], v[3], at);
            return;
        }
        case Directive::LookAt: {
            const auto v = numbers<9>(at);
            target_.look_at(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], at);
            return;
        }
        case Directive::ConcatTransform: target_.concat_transform(matrix(at), at); return;
        case Directive::Transform: target_.transform(matrix(at), at); return;
        case Directive::CoordinateSystem: target_.coordinate_system(string_argument(at, "a name"), at); return;
        case Directive::CoordSysTransform: target_.coord_sys_transform(string_argument(at, "a name"), at); return;
        case Directive::ActiveTransform: {
            const Token& t = argument(at, "All, StartTime or EndTime");
            if (t.kind != Token::Kind::Word || (t.text != "All" && t.text != "StartTime" && t.text != "EndTime"))
                fail(t.location(), "ActiveTransform: expected All, StartTime or EndTime, got " + describe_token(t));
            target_.active_transform(t.text, at);
            return;
        }
        case Directive::TransformTimes: {
            const auto v = numbers<2>(at);
            target_.transform_times(v[0], v[1], at);
            return;
        }
        case Directive::ReverseOrientation: target_.reverse_orientation(at); return;
        case Directive::AttributeBegin: target_.attribute_begin(at); return;
        case Directive::AttributeEnd: target_.attribute_end(at); return;
        case Directive::TransformBegin:
            if (!warned_transform_begin_) {
                target_.warn(at,
                             "TransformBegin/TransformEnd are deprecated in pbrt-v4; read as "
                             "AttributeBegin/AttributeEnd");
                warned_transform_begin_ = true;
            }
            target_.attribute_begin(at);
            return;
        case Directive::TransformEnd: target_.attribute_end(at); return;
        case Directive::Attribute: {
            std::string which = name_then(at, "shape, light, material, medium or texture", params);
            target_.attribute(which, std::move(params), at);
            return;
        }
        case Directive::Option: {
            Token declaration = argument(at, "an option's \"name\" as a quoted string");
            if (declaration.kind != Token::Kind::String)
                fail(declaration.location(),
                     "Option: expected the option's \"name\" as a quoted string, got " + describe_token(declaration));
            const Parameter value = read_parameter(tokens_, declaration, true);
            target_.option(value.name, value, at);
            return;
        }
        case Directive::ColorSpace: target_.color_space(string_argument(at, "a color space's name"), at); return;
        case Directive::Camera: {
            std::string type = name_then(at, "the camera's type", params);
            target_.camera(type, std::move(params), at);
            return;
        }
        case Directive::Film: {
            std::string type = name_then(at, "the film's type", params);
            target_.film(type, std::move(params), at);
            return;
        }
        case Directive::PixelFilter: {
            std::string type = name_then(at, "the filter's type", params);
            target_.pixel_filter(type, std::move(params), at);
            return;
        }
        case Directive::Sampler: {
            std::string type = name_then(at, "the sampler's type", params);
            target_.sampler(type, std::move(params), at);
            return;
        }
        case Directive::Integrator: {
            std::string type = name_then(at, "the integrator's type", params);
            target_.integrator(type, std::move(params), at);
            return;
        }
        case Directive::Accelerator: {
            std::string type = name_then(at, "the accelerator's type", params);
            target_.accelerator(type, std::move(params), at);
            return;
        }
        case Directive::MakeNamedMedium: {
            std::string name = name_then(at, "the medium's name", params);
            target_.make_named_medium(name, std::move(params), at);
            return;
        }
        case Directive::MediumInterface: {
            // One name for both sides, or inside then outside (pbrt-v4: a second quoted string).
            const std::string inside = string_argument(at, "a medium's name");
            std::string outside = inside;
            if (tokens_.peek() && tokens_.peek()->kind == Token::Kind::String) outside = string_argument(at, "");
            target_.medium_interface(inside, outside, at);
            return;
        }
        case Directive::WorldBegin: target_.world_begin(at); return;
        case Directive::WorldEnd:
            target_.warn(at, "WorldEnd is pbrt-v3's and means nothing in pbrt-v4; ignored");
            return;
        case Directive::Texture: {
            const std::string name = string_argument(at, "the texture's name");
            const std::string value_type = string_argument(at, "the texture's value type (\"spectrum\" or \"float\")");
            std::string type = name_then(at, "the texture's class", params);
            target_.texture(name, value_type, type, std::move(params), at);
            return;
        }
        case Directive::Material: {
            std::string type = name_then(at, "the material's type", params);
            target_.material(type, std::move(params), at);
            return;
        }
        case Directive::MakeNamedMaterial: {
            std::string name = name_then(at, "the material's name", params);
            target_.make_named_material(name, std::move(params), at);
            return;
        }
        case Directive::NamedMaterial: target_.named_material(string_argument(at, "a material's name"), at); return;
        case Directive::LightSource: {
            std::string type = name_then(at, "the light's type", params);
            target_.light_source(type, std::move(params), at);
            return;
        }
        case Directive::AreaLightSource: {
            std::string type = name_then(at, "the area light's type", params);
            target_.area_light_source(type, std::move(params), at);
            return;
        }
        case Directive::Shape: {
            std::string type = name_then(at, "the shape's type", params);
            target_.shape(type, std::move(params), at);
            return;
        }
        case Directive::ObjectBegin: target_.object_begin(string_argument(at, "the object's name"), at); return;
        case Directive::ObjectEnd: target_.object_end(at); return;
        case Directive::ObjectInstance: target_.object_instance(string_argument(at, "an object's name"), at); return;
        case Directive::Include:
        case Directive::Import: {
            // pbrt-v4 parses an Import's file in parallel into a copy of the graphics state; read
            // in order, as an Include, it defines the same scene.
            const Token directive = word_;
            tokens_.include(string_argument(at, "a file name"), directive);
            return;
        }
    }
}

}  // namespace

void parse_file(const std::filesystem::path& file, Target& target, const ParseOptions& options) {
    Parser parser(target, options);
    parser.tokens().open_main_file(file);
    parser.run();
}

void parse_string(std::string_view text, const std::filesystem::path& name, Target& target,
                  const ParseOptions& options) {
    Parser parser(target, options);
    parser.tokens().open_main_text(text, name);
    parser.run();
}

}  // namespace candela::pbrt
