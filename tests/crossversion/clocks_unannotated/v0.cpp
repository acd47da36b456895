// v0 of the clocks pair, built without its annotation file: no clock is declared.
#include "clocks/v0.cpp"
