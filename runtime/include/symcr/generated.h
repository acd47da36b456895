/* The part of the contract between the code symcr-gen emits and the runtime that C and C++
 * share (C99 or C++11): the generated C code of a C source includes it, and so do
 * <symcr/generated.hpp> and the C and C++ APIs, so that each declaration here is the one both
 * languages compile against. User code never needs to include it. Change it only together
 * with the generator. */
#ifndef SYMCR_GENERATED_H
#define SYMCR_GENERATED_H

#ifdef __cplusplus
namespace symcr {
/* The tables describing a program's checkpointed state (<symcr/generated.hpp>). */
struct Schema;
}  // namespace symcr
/* In C++ the schema handle is symcr::Schema itself: no casts between the two APIs. */
typedef symcr::Schema symcr_schema;
extern "C" {
#else
typedef struct symcr_schema symcr_schema;
#endif

/* How restore creates and destroys a heap object of a type (one restore must create for a
 * pointer, or stage for a container); C++'s symcr::Lifecycle. The generated code of a C
 * source defines one per such type with calloc and free. */
struct symcr_lifecycle {
  void* (*create)(void);         /* new T() (value-initialised) */
  void (*destroy)(void* object); /* delete static_cast<T*>(object) */
  /* kTypeDynamicType: what the vtable pointer of an object whose dynamic type is T holds (the
   * address point of T's vtable, Itanium C++ ABI); else null (always null in C). */
  const void* vtable;
};

/* The program's schema, defined by the code symcr-gen emits for a target. The API forms that
 * take no schema use it; it is weak so that a program without generated code links and gets a
 * clear "no schema" error (NULL here) instead. */
const symcr_schema* symcr_program_schema(void) __attribute__((weak));

#ifdef __cplusplus
}
#endif

#endif /* SYMCR_GENERATED_H */
