// Per-type operation tables for standard library types, instantiated by generated code:
//   static const symcr::ContainerOps* ops = &symcr::ops::container<std::vector<int>>::table;
// These are the only pieces of generated code that are not plain data: everything else the
// runtime derives from offsets and sizes in the schema.
// C++11 and every later dialect: the program's own code includes this header through the
// generated wrappers, in the program's dialect. std::optional and std::variant exist, and are
// supported, from C++17 on.
#ifndef SYMCR_OPS_HPP
#define SYMCR_OPS_HPP

#include <cstddef>
#include <iterator>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>
#if __cplusplus >= 201703L
#include <optional>
#include <variant>
#endif

#include "symcr/generated.hpp"

namespace symcr {
namespace ops {

// destroy() deletes an object as its exact (dynamic) class, which generated code chose by its
// vtable: correct without a virtual destructor, which -Wdelete-non-virtual-dtor cannot know.
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdelete-non-virtual-dtor"
#endif
template <typename T>
struct lifecycle {
  static void* create() { return new T(); }
  static void destroy(void* object) { delete static_cast<T*>(object); }
  static constexpr Lifecycle table{&create, &destroy, nullptr};
};
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

template <typename S>
struct string {
  typedef typename S::value_type Char;
  static std::size_t size(const void* s) { return static_cast<const S*>(s)->size(); }
  static const void* data(const void* s) { return static_cast<const S*>(s)->data(); }
  static void assign(void* s, const void* chars, std::size_t n) {
    static_cast<S*>(s)->assign(static_cast<const Char*>(chars), n);
  }
  static constexpr StringOps table{&size, &data, &assign};
};

namespace detail {
template <typename... T>
struct make_void {
  typedef void type;
};
template <typename... T>
using void_t = typename make_void<T...>::type;

template <typename C, typename = void>
struct has_push_back : std::false_type {};
template <typename C>
struct has_push_back<C, void_t<decltype(std::declval<C&>().emplace_back())>> : std::true_type {};
template <typename C, typename = void>
struct has_reserve : std::false_type {};
template <typename C>
struct has_reserve<C, void_t<decltype(std::declval<C&>().reserve(std::size_t{}))>>
    : std::true_type {};
template <typename C, typename = void>
struct has_size : std::false_type {};
template <typename C>
struct has_size<C, void_t<decltype(std::declval<const C&>().size())>> : std::true_type {};

template <typename C>
struct is_contiguous_vector : std::false_type {};
template <typename T, typename A>
struct is_contiguous_vector<std::vector<T, A>> : std::true_type {};

// The element type restore stages for associative containers: pair<const K, V> becomes
// pair<K, V> so the key can be filled in before insertion.
template <typename V>
struct staged {
  typedef V type;
};
template <typename K, typename V>
struct staged<std::pair<const K, V>> {
  typedef std::pair<K, V> type;
};

// What an associative insert returned: an iterator (multi-containers, always inserted) or
// (iterator, inserted).
template <typename Iterator>
void* inserted_element(Iterator it) {
  return const_cast<void*>(static_cast<const void*>(&*it));
}
template <typename Iterator>
void* inserted_element(std::pair<Iterator, bool> result) {
  return result.second ? const_cast<void*>(static_cast<const void*>(&*result.first)) : nullptr;
}
}  // namespace detail

// The type the generator must describe (and give a Lifecycle) as a container's element:
// value_type for sequences and sets, pair<K, V> (not pair<const K, V>) for maps.
template <typename C>
using element_t = typename detail::staged<typename C::value_type>::type;

// Each operation that only some containers have is chosen by overload on a constant (tag
// dispatch), so that only the one that applies is instantiated.
template <typename C>
struct container {
  typedef typename C::value_type Value;
  typedef std::integral_constant<bool, detail::has_push_back<C>::value> Sequence;
  typedef std::integral_constant<bool, detail::is_contiguous_vector<C>::value &&
                                           !std::is_same<Value, bool>::value>
      Contiguous;
  static constexpr bool is_sequence = Sequence::value;
  static constexpr bool is_contiguous = Contiguous::value;

  static std::size_t size(const void* c) {
    return size_of(*static_cast<const C*>(c), detail::has_size<C>());
  }
  static void for_each(const void* c, void (*visit)(void*, const void*), void* context) {
    const C& self = *static_cast<const C*>(c);
    for (typename C::const_iterator it = self.begin(); it != self.end(); ++it) {
      visit(context, &*it);
    }
  }
  static void* element_at(void* c, std::size_t i) {
    C& self = *static_cast<C*>(c);
    if (i >= size(c)) return nullptr;
    typename C::iterator it = self.begin();
    std::advance(
        it, static_cast<typename std::iterator_traits<typename C::iterator>::difference_type>(i));
    // Associative elements are const (keys); restore only writes through pointers it owns.
    return const_cast<void*>(static_cast<const void*>(&*it));
  }
  static void clear(void* c) { static_cast<C*>(c)->clear(); }
  static void reserve(void* c, std::size_t n) {
    reserve_in(*static_cast<C*>(c), n, detail::has_reserve<C>());
  }
  static void* append(void* c) { return append_to(*static_cast<C*>(c), Sequence()); }
  static void* insert(void* c, void* staged) {
    return insert_into(*static_cast<C*>(c), staged, Sequence());
  }
  static const void* contiguous_data(const void* c) {
    return data_of(*static_cast<const C*>(c), Contiguous());
  }
  static void* resize_default(void* c, std::size_t n) {
    return resize(*static_cast<C*>(c), n, Contiguous());
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

 private:
  static std::size_t size_of(const C& self, std::true_type) { return self.size(); }
  static std::size_t size_of(const C& self, std::false_type) {
    return static_cast<std::size_t>(std::distance(self.begin(), self.end()));
  }
  static void reserve_in(C& self, std::size_t n, std::true_type) { self.reserve(n); }
  static void reserve_in(C&, std::size_t, std::false_type) {}
  static void* append_to(C& self, std::true_type) {
    self.emplace_back();  // returns void before C++17
    return &self.back();
  }
  static void* append_to(C&, std::false_type) { return nullptr; }
  static void* insert_into(C&, void*, std::true_type) { return nullptr; }
  static void* insert_into(C& self, void* staged, std::false_type) {
    return detail::inserted_element(self.insert(std::move(*static_cast<element_t<C>*>(staged))));
  }
  static const void* data_of(const C& self, std::true_type) { return self.data(); }
  static const void* data_of(const C&, std::false_type) { return nullptr; }
  static void* resize(C& self, std::size_t n, std::true_type) {
    self.resize(n);
    return self.data();
  }
  static void* resize(C&, std::size_t, std::false_type) { return nullptr; }
};

#if __cplusplus >= 201703L
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
#endif

template <typename P>
struct unique_ptr {
  typedef typename P::element_type T;
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
  typedef typename P::element_type T;
  static const void* get(const void* p) { return static_cast<const P*>(p)->get(); }
  static void* make_holder() { return new P(std::make_shared<T>()); }
  static void* holder_get(void* holder) { return static_cast<P*>(holder)->get(); }
  static void assign_from_holder(void* p, const void* holder) {
    *static_cast<P*>(p) = *static_cast<const P*>(holder);
  }
  static void destroy_holder(void* holder) { delete static_cast<P*>(holder); }
  static void reset(void* p) { static_cast<P*>(p)->reset(); }
  static constexpr SharedPtrOps table{
      &get, &make_holder, &holder_get, &assign_from_holder, &destroy_holder, &reset};
};

// Before C++17 a static constexpr member that is odr-used (its address taken) needs a
// definition outside the class; from C++17 on it is inline and this would be redundant.
#if __cplusplus < 201703L
template <typename T>
constexpr Lifecycle lifecycle<T>::table;
template <typename S>
constexpr StringOps string<S>::table;
template <typename C>
constexpr ContainerOps container<C>::table;
template <typename C>
constexpr bool container<C>::is_sequence;
template <typename C>
constexpr bool container<C>::is_contiguous;
template <typename P>
constexpr UniquePtrOps unique_ptr<P>::table;
template <typename P>
constexpr SharedPtrOps shared_ptr<P>::table;
#endif

// Byte offset of a member given by a member pointer, for private members reached through the
// explicit-instantiation access technique (offsetof cannot name them).
template <typename Class, typename Member>
std::uint32_t offset_of(Member Class::*member) {
  alignas(Class) static unsigned char storage[sizeof(Class)];
  const Class* object = reinterpret_cast<const Class*>(storage);
  return static_cast<std::uint32_t>(reinterpret_cast<const unsigned char*>(&(object->*member)) -
                                    storage);
}

}  // namespace ops
}  // namespace symcr

#endif  // SYMCR_OPS_HPP
