#pragma once
// Reads parameter lists (`"float radius" 3`, `"point3 P" [ 0 0 0 1 0 0 ]`) off the token stream
// and checks that the values fit the declared type, each error located at the value at fault:
// numbers for the numeric types (integers for integer), quoted strings for string and texture,
// true/false for bool (bare as pbrt-v4 writes them, or quoted as pbrt-v3 did), and for spectrum
// either (lambda, value) pairs or one name or file. Counts must be whole points, vectors or pairs.
#include <string_view>

#include "candela/formats/pbrt/pbrt_parameters.h"
#include "candela/formats/pbrt/pbrt_token_stream.h"

namespace candela::pbrt {

// The number a bare word spells (std::from_chars, pbrt-v4's syntax plus a leading '+'). Words
// that are not numbers, NaN, infinities and numbers beyond double's range (1e999) are errors at
// the token, the message starting with `context`.
double parse_number(const Token& word, std::string_view context);

// A token as an error message names it: "[", "]", the string "...", or the quoted word.
std::string describe_token(const Token& t);

// Every parameter that follows a directive: the parameters end at the first token that is not a
// quoted string.
ParameterList read_parameters(TokenStream& tokens);

// The values of the parameter declared by `declaration`, already taken. With `untyped_allowed`
// (Option's "name" value) a declaration without a type takes it from its values: bool for
// true/false, string for quoted strings, float for numbers.
Parameter read_parameter(TokenStream& tokens, const Token& declaration, bool untyped_allowed);

}  // namespace candela::pbrt
