// Per-type operation tables for standard library types, instantiated by generated code:
//   static const symcr::ContainerOps* ops = &symcr::ops::container<std::vector<int>>::table;
// These are the only pieces of generated code that are not plain data: everything else the
// runtime derives from offsets and sizes in the schema.
#ifndef SYMCR_OPS_HPP
#define SYMCR_OPS_HPP

#include <cstddef>
#include <iterator>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "symcr/schema.hpp"

namespace symcr::ops {

template <typename T>
struct lifecycle {
  static void* create() { return new T(); }
  static void destroy(void* object) { delete static_cast<T*>(object); }
  static constexpr Lifecycle table{&create, &destroy};
};

template <typename S>
struct string {
  using Char = typename S::value_type;
  static std::size_t size(const void* s) { return static_cast<const S*>(s)->size(); }
  static const void* data(const void* s) { return static_cast<const S*>(s)->data(); }
  static void assign(void* s, const void* chars, std::size_t n) {
    static_cast<S*>(s)->assign(static_cast<const Char*>(chars), n);
  }
  static constexpr StringOps table{&size, &data, &assign};
};

namespace detail {
template <typename C, typename = void>
struct has_push_back : std::false_type {};
template <typename C>
struct has_push_back<C, std::void_t<decltype(std::declval<C&>().emplace_back())>>
    : std::true_type {};
template <typename C, typename = void>
struct has_reserve : std::false_type {};
template <typename C>
struct has_reserve<C, std::void_t<decltype(std::declval<C&>().reserve(std::size_t{}))>>
    : std::true_type {};
template <typename C, typename = void>
struct has_size : std::false_type {};
template <typename C>
struct has_size<C, std::void_t<decltype(std::declval<const C&>().size())>> : std::true_type {};

template <typename C>
struct is_contiguous_vector : std::false_type {};
template <typename T, typename A>
struct is_contiguous_vector<std::vector<T, A>> : std::true_type {};

// The element type restore stages for associative containers: pair<const K, V> becomes
// pair<K, V> so the key can be filled in before insertion.
template <typename V>
struct staged {
  using type = V;
};
template <typename K, typename V>
struct staged<std::pair<const K, V>> {
  using type = std::pair<K, V>;
};
}  // namespace detail

// The type the generator must describe (and give a Lifecycle) as a container's element:
// value_type for sequences and sets, pair<K, V> (not pair<const K, V>) for maps.
template <typename C>
using element_t = typename detail::staged<typename C::value_type>::type;

template <typename C>
struct container {
  using Value = typename C::value_type;
  static constexpr bool is_sequence = detail::has_push_back<C>::value;

  static std::size_t size(const void* c) {
    const C& self = *static_cast<const C*>(c);
    if constexpr (detail::has_size<C>::value) {
      return self.size();
    } else {
      return static_cast<std::size_t>(std::distance(self.begin(), self.end()));
    }
  }
  static void for_each(const void* c, void (*visit)(void*, const void*), void* context) {
    for (const Value& element : *static_cast<const C*>(c)) visit(context, &element);
  }
  static void* element_at(void* c, std::size_t i) {
    C& self = *static_cast<C*>(c);
    if (i >= size(c)) return nullptr;
    auto it = self.begin();
    std::advance(it, static_cast<typename std::iterator_traits<decltype(it)>::difference_type>(i));
    // Associative elements are const (keys); restore only writes through pointers it owns.
    return const_cast<void*>(static_cast<const void*>(&*it));
  }
  static void clear(void* c) { static_cast<C*>(c)->clear(); }
  static void reserve(void* c, std::size_t n) {
    if constexpr (detail::has_reserve<C>::value) static_cast<C*>(c)->reserve(n);
    (void)c;
    (void)n;
  }
  static void* append(void* c) {
    if constexpr (is_sequence) {
      return &static_cast<C*>(c)->emplace_back();
    } else {
      (void)c;
      return nullptr;
    }
  }
  static void* insert(void* c, void* staged) {
    if constexpr (is_sequence) {
      (void)c;
      (void)staged;
      return nullptr;
    } else {
      auto result = static_cast<C*>(c)->insert(std::move(*static_cast<element_t<C>*>(staged)));
      if constexpr (std::is_same_v<decltype(result), typename C::iterator>) {
        return const_cast<void*>(static_cast<const void*>(&*result));  // multi-containers
      } else {
        return result.second ? const_cast<void*>(static_cast<const void*>(&*result.first))
                             : nullptr;
      }
    }
  }
  static constexpr bool is_contiguous =
      detail::is_contiguous_vector<C>::value && !std::is_same_v<Value, bool>;
  static const void* contiguous_data(const void* c) {
    if constexpr (is_contiguous) {
      return static_cast<const C*>(c)->data();
    } else {
      (void)c;
      return nullptr;
    }
  }
  static void* resize_default(void* c, std::size_t n) {
    if constexpr (is_contiguous) {
      static_cast<C*>(c)->resize(n);
      return static_cast<C*>(c)->data();
    } else {
      (void)c;
      (void)n;
      return nullptr;
    }
  }
  static constexpr ContainerOps table{&size,
                                      &for_each,
                                      &element_at,
                                      &clear,
                                      &reserve,
                                      is_sequence ? &append : nullptr,
                                      is_sequence ? nullptr : &insert,
                                      is_contiguous ? &contiguous_data : nullptr,
                                      is_contiguous ? &resize_default : nullptr};
};

template <typename O>
struct optional {
  static const void* get(const void* o) {
    const O& self = *static_cast<const O*>(o);
    return self.has_value() ? &*self : nullptr;
  }
  static void* emplace(void* o) { return &static_cast<O*>(o)->emplace(); }
  static void reset(void* o) { static_cast<O*>(o)->reset(); }
  static constexpr OptionalOps table{&get, &emplace, &reset};
};

template <typename V>
struct variant {
  static constexpr std::size_t kSize = std::variant_size_v<V>;
  static std::uint32_t index(const void* v) {
    const V& self = *static_cast<const V*>(v);
    return self.valueless_by_exception() ? kNoType : static_cast<std::uint32_t>(self.index());
  }
  static const void* get(const void* v) {
    return std::visit([](const auto& alternative) -> const void* { return &alternative; },
                      *static_cast<const V*>(v));
  }
  template <std::size_t I>
  static void* emplace_at(void* v) {
    return &static_cast<V*>(v)->template emplace<I>();
  }
  template <std::size_t... I>
  static void* emplace_dispatch(void* v, std::uint32_t index, std::index_sequence<I...>) {
    void* result = nullptr;
    ((index == I ? (result = emplace_at<I>(v), 0) : 0), ...);
    return result;
  }
  static void* emplace(void* v, std::uint32_t index) {
    return emplace_dispatch(v, index, std::make_index_sequence<kSize>{});
  }
  static constexpr VariantOps table{&index, &get, &emplace};
};

template <typename P>
struct unique_ptr {
  using T = typename P::element_type;
  static const void* get(const void* p) { return static_cast<const P*>(p)->get(); }
  static void* make(void* p) {
    static_cast<P*>(p)->reset(new T());
    return static_cast<P*>(p)->get();
  }
  static void reset(void* p) { static_cast<P*>(p)->reset(); }
  static constexpr UniquePtrOps table{&get, &make, &reset};
};

template <typename P>
struct shared_ptr {
  using T = typename P::element_type;
  static const void* get(const void* p) { return static_cast<const P*>(p)->get(); }
  static void* make_holder() { return new P(std::make_shared<T>()); }
  static void* holder_get(void* holder) { return static_cast<P*>(holder)->get(); }
  static void assign_from_holder(void* p, const void* holder) {
    *static_cast<P*>(p) = *static_cast<const P*>(holder);
  }
  static void destroy_holder(void* holder) { delete static_cast<P*>(holder); }
  static void reset(void* p) { static_cast<P*>(p)->reset(); }
  static constexpr SharedPtrOps table{&get,          &make_holder,     &holder_get,
                                      &assign_from_holder, &destroy_holder, &reset};
};

// Byte offset of a member given by a member pointer, for private members reached through the
// explicit-instantiation access technique (offsetof cannot name them).
template <typename Class, typename Member>
std::uint32_t offset_of(Member Class::*member) {
  alignas(Class) static unsigned char storage[sizeof(Class)];
  const Class* object = reinterpret_cast<const Class*>(storage);
  return static_cast<std::uint32_t>(reinterpret_cast<const unsigned char*>(&(object->*member)) -
                                    storage);
}

}  // namespace symcr::ops

#endif  // SYMCR_OPS_HPP
