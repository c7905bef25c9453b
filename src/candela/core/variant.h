#pragma once
// Closed sets of value types (materials, lights, filters) are Variants dispatched with visit.
// The aliases let a GPU backend swap the implementation without touching call sites.
#include <variant>

namespace candela {
template <class... Ts>
using Variant = std::variant<Ts...>;

using std::visit;
using std::holds_alternative;
using std::get_if;

// Builds a visitor from lambdas: visit(Overloaded{[](const A&) {...}, [](const B&) {...}}, v).
template <class... Fs>
struct Overloaded : Fs... {
    using Fs::operator()...;
};
// C++20 deduces this for aggregates; clang before 17 (the sanitizer build's clang 14) does not.
template <class... Fs>
Overloaded(Fs...) -> Overloaded<Fs...>;
}  // namespace candela
