// Non-intrusive access to private data members, for the hand-written cereal / Boost serialize
// functions of the specimen's classes (Copter, AP_AHRS, AP_Mission keep their state private, as
// ArduPilot's classes do, and the benchmark must not edit the autopilot's sources).
//
// The standard way: an explicit instantiation may name a private member in its template
// arguments ([temp.spec.general]/6), and the instantiated class template defines a friend
// function that hands the member pointer out. `auto` spares naming private member types.
//
//   SPECIMEN_BENCH_GRANT(Copter, ap);          // at namespace scope, once
//   auto& flags = member(c, Copter_ap{});      // c.ap
#ifndef SYMCR_BENCHMARKS_SPECIMEN_ACCESS_HPP
#define SYMCR_BENCHMARKS_SPECIMEN_ACCESS_HPP

namespace specimen_bench::access {

template <class Tag, auto Member>
struct Grant {
  friend constexpr auto member_pointer(Tag) { return Member; }
};

template <class Object, class Tag>
constexpr auto& member(Object& object, Tag tag) {
  return object.*member_pointer(tag);
}

}  // namespace specimen_bench::access

// Declares the tag Class_field (found by ADL) and instantiates its grant.
#define SPECIMEN_BENCH_GRANT(Class, field)                                            \
  namespace specimen_bench::access {                                                  \
  struct Class##_##field {                                                            \
    friend constexpr auto member_pointer(Class##_##field);                            \
  };                                                                                  \
  template struct Grant<Class##_##field, &Class::field>;                              \
  }

#endif  // SYMCR_BENCHMARKS_SPECIMEN_ACCESS_HPP
