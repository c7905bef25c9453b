#include "candela/formats/pbrt/pbrt_parameter_reader.h"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <utility>

#include "candela/formats/pbrt/pbrt_directives.h"

namespace candela::pbrt {

namespace {

// What values a parameter type holds, and how many make one item (a point3 is 3 numbers).
enum class Values { Numbers, Integers, Strings, Bools, Spectrum, Inferred };

struct TypeInfo {
    std::string_view name;
    Values values;
    size_t arity;
};

// pbrt-v4's types (ParsedParameter; paramdict.cpp), with pbrt-v3's point, vector, normal and color.
constexpr std::array<TypeInfo, 17> kTypes{{
    {"integer", Values::Integers, 1},
    {"float", Values::Numbers, 1},
    {"point2", Values::Numbers, 2},
    {"vector2", Values::Numbers, 2},
    {"point3", Values::Numbers, 3},
    {"vector3", Values::Numbers, 3},
    {"normal", Values::Numbers, 3},
    {"normal3", Values::Numbers, 3},
    {"point", Values::Numbers, 3},
    {"vector", Values::Numbers, 3},
    {"color", Values::Numbers, 3},
    {"rgb", Values::Numbers, 3},
    {"blackbody", Values::Numbers, 1},
    {"spectrum", Values::Spectrum, 2},
    {"bool", Values::Bools, 1},
    {"string", Values::Strings, 1},
    {"texture", Values::Strings, 1},
}};

const TypeInfo* find_type(std::string_view name) {
    for (const TypeInfo& t : kTypes)
        if (t.name == name) return &t;
    return nullptr;
}

// Directives start with a capital letter; numbers never do, so a list of numbers skips the lookup.
bool might_be_directive(std::string_view word) { return !word.empty() && word[0] >= 'A' && word[0] <= 'Z'; }

// First the first byte: in a list of numbers almost every word fails there.
bool is_bool_word(const Token& t) {
    return t.kind == Token::Kind::Word && !t.text.empty() && (t.text[0] == 't' || t.text[0] == 'f') &&
           (t.text == "true" || t.text == "false");
}

std::string quote_text(std::string_view s) { return "\"" + std::string(s) + "\""; }

// pbrt-v4's parseInt: an optional sign and decimal digits, within 32 bits.
bool is_int32(std::string_view s) {
    const bool negative = !s.empty() && s[0] == '-';
    if (!s.empty() && (s[0] == '+' || s[0] == '-')) s.remove_prefix(1);
    if (s.empty()) return false;
    const int64_t limit = int64_t(std::numeric_limits<int32_t>::max()) + (negative ? 1 : 0);
    int64_t value = 0;
    for (const char c : s) {
        if (c < '0' || c > '9') return false;
        value = 10 * value + (c - '0');
        if (value > limit) return false;
    }
    return true;
}

// The parts of `"type name"`, split at spaces and tabs.
std::pair<std::string_view, std::string_view> split_declaration(const Token& declaration, bool untyped_allowed) {
    std::array<std::string_view, 3> words;
    size_t count = 0;
    std::string_view rest = declaration.text;
    while (count < words.size()) {
        const size_t begin = rest.find_first_not_of(" \t");
        if (begin == std::string_view::npos) break;
        rest.remove_prefix(begin);
        const size_t end = std::min(rest.find_first_of(" \t"), rest.size());
        words[count++] = rest.substr(0, end);
        rest.remove_prefix(end);
    }
    const std::string hint = " (expected \"type name\", e.g. \"float radius\")";
    if (count == 0) fail(declaration.location(), "an empty parameter declaration" + hint);
    if (count == 1) {
        if (untyped_allowed) return {{}, words[0]};
        fail(declaration.location(), "parameter " + quote_text(declaration.text) + " has no type" + hint);
    }
    if (count > 2)
        fail(declaration.location(), "malformed parameter declaration " + quote_text(declaration.text) + hint);
    return {words[0], words[1]};
}

class ValueReader {
  public:
    ValueReader(Parameter& p, const TypeInfo* type, std::string context)
        : p_(p), values_(type ? type->values : Values::Inferred), context_(std::move(context)) {}

    void add(const Token& v) {
        if (values_ == Values::Inferred) values_ = infer(v);
        const bool bool_word = is_bool_word(v);
        switch (values_) {
            case Values::Bools:
                if (bool_word || (v.kind == Token::Kind::String && (v.text == "true" || v.text == "false"))) {
                    p_.bools.push_back(v.text == "true");
                    return;
                }
                fail(v.location(), context_ + ": expected true or false, got " + describe_token(v));
            case Values::Strings:
                if (v.kind == Token::Kind::String) {
                    p_.strings.push_back(v.text);
                    return;
                }
                fail(v.location(), context_ + ": expected a quoted string, got " + describe_token(v));
            case Values::Spectrum:
                if (v.kind == Token::Kind::String) {
                    if (!p_.numbers.empty() || !p_.strings.empty())
                        fail(v.location(), context_ +
                                               ": a spectrum is (lambda, value) pairs or one name or file, got " +
                                               describe_token(v) + " after them");
                    p_.strings.push_back(v.text);
                    return;
                }
                if (!p_.strings.empty())
                    fail(v.location(),
                         context_ + ": a spectrum is one name or file or (lambda, value) pairs, not both");
                add_number(v);
                return;
            case Values::Integers:
                if (v.kind == Token::Kind::Word && !bool_word && !is_int32(v.text)) {
                    parse_number(v, context_);  // a word that is no number gets that message
                    fail(v.location(), context_ + ": expected a 32-bit integer, got " + describe_token(v));
                }
                add_number(v);
                return;
            case Values::Numbers:
            case Values::Inferred: add_number(v); return;
        }
    }

  private:
    static Values infer(const Token& v) {
        if (v.kind == Token::Kind::String) return Values::Strings;
        if (is_bool_word(v)) return Values::Bools;
        return Values::Numbers;
    }
    void add_number(const Token& v) {
        if (v.kind != Token::Kind::Word || is_bool_word(v))
            fail(v.location(), context_ + ": expected a number, got " + describe_token(v));
        p_.numbers.push_back(parse_number(v, context_));
    }

    Parameter& p_;
    Values values_;
    std::string context_;
};

}  // namespace

std::string describe_token(const Token& t) {
    switch (t.kind) {
        case Token::Kind::Open: return "[";
        case Token::Kind::Close: return "]";
        case Token::Kind::String: return "the string " + quote_text(t.text);
        case Token::Kind::Word: break;
    }
    return quote_text(t.text);
}

double parse_number(const Token& word, std::string_view context) {
    std::string_view s = word.text;
    if (s.size() > 1 && s[0] == '+' && s[1] != '-' && s[1] != '+') s.remove_prefix(1);
    double value = 0;
    const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), value);
    if (s.empty() || end != s.data() + s.size() || error == std::errc::invalid_argument)
        fail(word.location(), std::string(context) + ": expected a number, got " + describe_token(word));
    if (error == std::errc::result_out_of_range) {
        // from_chars reports underflow too; strtod tells 1e-999 (0, as pbrt-v4 reads it) from 1e999.
        value = std::strtod(std::string(s).c_str(), nullptr);
        if (std::isinf(value))
            fail(word.location(),
                 std::string(context) + ": " + quote_text(word.text) + " is beyond the range of a double");
    }
    if (!std::isfinite(value))
        fail(word.location(), std::string(context) + ": expected a finite number, got " + quote_text(word.text));
    return value;
}

Parameter read_parameter(TokenStream& tokens, const Token& declaration, bool untyped_allowed) {
    Parameter p;
    p.location = declaration.location();
    const auto [type_name, name] = split_declaration(declaration, untyped_allowed);
    const TypeInfo* type = nullptr;
    if (!type_name.empty()) {
        type = find_type(type_name);
        if (!type)
            fail(p.location, "unknown parameter type " + quote_text(type_name) + " in " + quote_text(declaration.text) +
                                 " (pbrt-v4 knows integer, float, point2, vector2, point3, vector3, normal, "
                                 "normal3, rgb, spectrum, blackbody, bool, string, texture)");
        p.type = std::string(type_name);
    }
    p.name = std::string(name);
    const std::string context = quote_text(declaration.text);
    ValueReader reader(p, type, context);

    Token value;
    if (!tokens.next(value)) fail(p.location, context + " has no value (the file ends)");
    const Location first = value.location();
    if (value.kind == Token::Kind::Close) fail(first, context + ": unexpected ] (no [ opened a list)");
    if (value.kind == Token::Kind::Open) {
        for (;;) {
            if (!tokens.next(value)) fail(first, context + ": missing ] (the list runs to the end of the file)");
            if (value.kind == Token::Kind::Close) break;
            if (value.kind == Token::Kind::Open) fail(value.location(), context + ": unexpected [ inside a list");
            if (value.kind == Token::Kind::Word && might_be_directive(value.text) && find_directive(value.text))
                fail(first, context + ": missing ] (the list runs into " + value.text + " at " +
                                std::to_string(value.line) + ":" + std::to_string(value.column) + ")");
            reader.add(value);
        }
    } else {
        reader.add(value);
    }

    if (p.type.empty()) p.type = !p.bools.empty() ? "bool" : !p.strings.empty() ? "string" : "float";
    if (type && type->values == Values::Spectrum && p.strings.empty() && p.numbers.size() % 2 != 0)
        fail(first,
             context + " has " + std::to_string(p.numbers.size()) + " numbers; a spectrum needs (lambda, value) pairs");
    if (type && type->arity > 1 && type->values == Values::Numbers && p.numbers.size() % type->arity != 0)
        fail(first, context + " has " + std::to_string(p.numbers.size()) + " numbers; expected a multiple of " +
                        std::to_string(type->arity));
    return p;
}

ParameterList read_parameters(TokenStream& tokens) {
    ParameterList list;
    Token declaration;
    while (const Token* next = tokens.peek()) {
        if (next->kind != Token::Kind::String) break;
        tokens.next(declaration);
        list.push_back(read_parameter(tokens, declaration, false));
    }
    return list;
}

}  // namespace candela::pbrt
