# The warning flags of the strictest autopilot builds (ArduPilot's and PX4's -Werror sets, and
# the conversion, cast and shadowing warnings on top), under which symcr's generated code and
# headers compile without one diagnostic (generator/README.md, "Generated code and warning
# flags"). Used by crossversion.<pair>[.cxx<n>].strict_flags and generator.clang_compiles_*.
#   symcr_strict_warning_flags(<compiler id: GNU|Clang> <C|CXX> <result variable>)
# The result is empty for another compiler.
function(symcr_strict_warning_flags compiler_id language result)
  set(flags)
  if(compiler_id STREQUAL "GNU" AND language STREQUAL "CXX")
    set(flags -Wall -Wextra -Wdelete-non-virtual-dtor -Wshadow -Wcast-align=strict -Wundef
        -Wpointer-arith -Wconversion -Wsign-conversion -Wdouble-promotion -Wfloat-equal
        -Wmissing-declarations -Wsuggest-override -Wimplicit-fallthrough -Wlogical-op
        -Wduplicated-cond -Wformat=2 -Wuninitialized -Wmaybe-uninitialized -Wunused -Wpedantic
        -Wold-style-cast -Wuseless-cast -Wcast-qual -Wzero-as-null-pointer-constant
        -Wextra-semi -Wredundant-decls -Wnull-dereference -Winit-self -Wdisabled-optimization)
  elseif(compiler_id MATCHES "Clang" AND language STREQUAL "CXX")
    set(flags -Wall -Wextra -Wdelete-non-virtual-dtor -Wshadow-all -Wcast-align -Wundef
        -Wpointer-arith -Wconversion -Wsign-conversion -Wshorten-64-to-32 -Wdouble-promotion
        -Wfloat-equal -Wmissing-prototypes -Wmissing-variable-declarations -Wsuggest-override
        -Wimplicit-fallthrough -Wformat=2 -Wuninitialized -Wunused -Wpedantic -Wold-style-cast
        -Wcast-qual -Wzero-as-null-pointer-constant -Wextra-semi -Wnull-dereference)
  elseif(compiler_id STREQUAL "GNU" AND language STREQUAL "C")
    set(flags -Wall -Wextra -Wshadow -Wcast-align=strict -Wundef -Wpointer-arith -Wconversion
        -Wsign-conversion -Wdouble-promotion -Wfloat-equal -Wmissing-prototypes
        -Wstrict-prototypes -Wmissing-declarations -Wold-style-definition -Wredundant-decls
        -Wcast-qual -Wnull-dereference -Wformat=2 -Wlogical-op -Wduplicated-cond -Wpedantic)
  elseif(compiler_id MATCHES "Clang" AND language STREQUAL "C")
    set(flags -Wall -Wextra -Wshadow-all -Wcast-align -Wundef -Wpointer-arith -Wconversion
        -Wsign-conversion -Wdouble-promotion -Wfloat-equal -Wmissing-prototypes
        -Wmissing-variable-declarations -Wstrict-prototypes -Wcast-qual -Wnull-dereference
        -Wformat=2 -Wpedantic)
  endif()
  set(${result} ${flags} PARENT_SCOPE)
endfunction()
