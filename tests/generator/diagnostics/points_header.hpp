// A function defined in a header: symcr-gen copies only the target's sources.
#ifndef POINTS_HEADER_HPP
#define POINTS_HEADER_HPP
inline int inline_in_header() { return 1; }
void declared_only();
#endif
