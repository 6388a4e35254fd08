// ClosedSet<Ts...>: the one template behind every closed set of types in kiln (pbrt-v4's
// TaggedPointer, as a std::variant): shapes, BxDFs, materials, lights, light samplers, media,
// spectra, textures, texture mappings, cameras, samplers, filters. The full list of types is in
// one line, dispatch is a switch (no virtual calls), and every set speaks the same words:
//   Is<T>()      whether it holds a T (T the object type: for a set of pointers, the pointee)
//   GetIf<T>()   the T it holds, or nullptr
//   Dispatch(f)  f called with what it holds (the pointer, or a reference to the value)
//   Index()      which type, by position in the list
// A set's own class derives from it and gives its operations as methods that Dispatch (a
// method on the closed type, not a type query from outside). Asking for a type that is not in
// the set is a compile error.
#pragma once

#include <cstddef>
#include <type_traits>
#include <utility>
#include <variant>

namespace kiln {

namespace closed_set_detail {

// Whether alternative U holds a T: U is T, const T* or T*.
template <typename T, typename U>
inline constexpr bool Names =
    std::is_same_v<U, T> || std::is_same_v<U, const T*> || std::is_same_v<U, T*>;

// The first of Us that holds a T (void: none).
template <typename T, typename... Us>
struct Find {
    using type = void;
};
template <typename T, typename U, typename... Us>
struct Find<T, U, Us...> {
    using type = std::conditional_t<Names<T, U>, U, typename Find<T, Us...>::type>;
};

}  // namespace closed_set_detail

template <typename... Ts>
class ClosedSet {
  public:
    // The alternative that holds a T
    template <typename T>
    using Alternative = typename closed_set_detail::Find<T, Ts...>::type;
    // Whether V (a value, or a pointer to a pointee) is one of the set's alternatives exactly
    template <typename V>
    static constexpr bool Accepts =
        ((std::is_same_v<std::decay_t<V>, Ts> ||
          (std::is_pointer_v<std::decay_t<V>> &&
           std::is_same_v<const std::remove_pointer_t<std::decay_t<V>>*, Ts>)) ||
         ...);

    ClosedSet() = default;  // the first type, value-initialised (a null pointer for pointers)
    template <typename V>
    requires Accepts<V> ClosedSet(V&& value) : v(std::forward<V>(value)) {}

    template <typename T>
    bool Is() const {
        static_assert(!std::is_void_v<Alternative<T>>, "the type is not in this closed set");
        return std::holds_alternative<Alternative<T>>(v);
    }
    template <typename T>
    const T* GetIf() const {
        using U = Alternative<T>;
        static_assert(!std::is_void_v<U>, "the type is not in this closed set");
        const U* held = std::get_if<U>(&v);
        if (!held) return nullptr;
        if constexpr (std::is_pointer_v<U>)
            return *held;
        else
            return held;
    }
    template <typename F>
    decltype(auto) Dispatch(F&& f) const {
        return std::visit(std::forward<F>(f), v);
    }
    template <typename F>
    decltype(auto) Dispatch(F&& f) {
        return std::visit(std::forward<F>(f), v);
    }
    size_t Index() const { return v.index(); }

    // Same type and, for pointers, the same object (for values, equal values).
    friend bool operator==(const ClosedSet& a, const ClosedSet& b) { return a.v == b.v; }

  private:
    std::variant<Ts...> v;
};

}  // namespace kiln
