// X(p00) X(p01) ... X(pff): the many members and types the limit tests need. The _INNER copy is
// for use inside an X of SYMCR_REPEAT_256 (a macro is not expanded again inside its own
// expansion).
#ifndef SYMCR_TESTS_DEVICE_LIMITS_REPEAT_HPP
#define SYMCR_TESTS_DEVICE_LIMITS_REPEAT_HPP
#define SYMCR_REPEAT_16(X, p)                                                                     \
  X(p##0)                                                                                         \
  X(p##1) X(p##2) X(p##3) X(p##4) X(p##5) X(p##6) X(p##7) X(p##8) X(p##9) X(p##a) X(p##b) X(p##c) \
      X(p##d) X(p##e) X(p##f)
#define SYMCR_REPEAT_256(X, p)                                                           \
  SYMCR_REPEAT_16(X, p##0)                                                               \
  SYMCR_REPEAT_16(X, p##1) SYMCR_REPEAT_16(X, p##2) SYMCR_REPEAT_16(X, p##3)             \
      SYMCR_REPEAT_16(X, p##4) SYMCR_REPEAT_16(X, p##5) SYMCR_REPEAT_16(X, p##6)         \
          SYMCR_REPEAT_16(X, p##7) SYMCR_REPEAT_16(X, p##8) SYMCR_REPEAT_16(X, p##9)     \
              SYMCR_REPEAT_16(X, p##a) SYMCR_REPEAT_16(X, p##b) SYMCR_REPEAT_16(X, p##c) \
                  SYMCR_REPEAT_16(X, p##d) SYMCR_REPEAT_16(X, p##e) SYMCR_REPEAT_16(X, p##f)
#define SYMCR_REPEAT_INNER_16(X, p)                                                               \
  X(p##0)                                                                                         \
  X(p##1) X(p##2) X(p##3) X(p##4) X(p##5) X(p##6) X(p##7) X(p##8) X(p##9) X(p##a) X(p##b) X(p##c) \
      X(p##d) X(p##e) X(p##f)
#define SYMCR_REPEAT_INNER_256(X, p)                                                               \
  SYMCR_REPEAT_INNER_16(X, p##0)                                                                   \
  SYMCR_REPEAT_INNER_16(X, p##1) SYMCR_REPEAT_INNER_16(X, p##2) SYMCR_REPEAT_INNER_16(X, p##3)     \
      SYMCR_REPEAT_INNER_16(X, p##4) SYMCR_REPEAT_INNER_16(X, p##5) SYMCR_REPEAT_INNER_16(X, p##6) \
          SYMCR_REPEAT_INNER_16(X, p##7) SYMCR_REPEAT_INNER_16(X, p##8)                            \
              SYMCR_REPEAT_INNER_16(X, p##9) SYMCR_REPEAT_INNER_16(X, p##a)                        \
                  SYMCR_REPEAT_INNER_16(X, p##b) SYMCR_REPEAT_INNER_16(X, p##c)                    \
                      SYMCR_REPEAT_INNER_16(X, p##d) SYMCR_REPEAT_INNER_16(X, p##e)                \
                          SYMCR_REPEAT_INNER_16(X, p##f)

#endif  // SYMCR_TESTS_DEVICE_LIMITS_REPEAT_HPP
