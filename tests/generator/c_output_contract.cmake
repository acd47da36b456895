# The generated code of a C source defines its lifecycles with the runtime's own type, from
# <symcr/generated.h> (which C++'s symcr::Lifecycle is), and declares no struct of its own whose
# layout nothing would check against the C++ side. -DFILE=<a C wrapper that has lifecycles>
file(READ ${FILE} text)
if(NOT text MATCHES "#include <symcr/generated.h>")
  message(FATAL_ERROR "${FILE} does not include <symcr/generated.h>")
endif()
if(NOT text MATCHES "const struct symcr_lifecycle symcr_gen_c_lifecycle_")
  message(FATAL_ERROR "${FILE} defines no lifecycle of type struct symcr_lifecycle")
endif()
# The program's source is #included, not copied: any struct body here is the generator's.
if(text MATCHES "struct[ \t\n]+[A-Za-z_0-9]*[ \t\n]*{")
  message(FATAL_ERROR "${FILE} defines a struct of its own: ${CMAKE_MATCH_0}")
endif()
