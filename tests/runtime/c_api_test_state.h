/* The state of the C API test program: plain C structs, defined in c_api_test.c and described
 * to symcr by c_api_test_schema.cpp (standing in for the code symcr-gen would generate). */
#ifndef SYMCR_TESTS_RUNTIME_C_API_TEST_STATE_H
#define SYMCR_TESTS_RUNTIME_C_API_TEST_STATE_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

struct c_vehicle {
  int32_t altitude_cm;
  uint16_t waypoint;
  double heading;
  int16_t trims[3];
};

extern struct c_vehicle c_vehicle_state;
extern uint32_t c_tick_count;

#ifdef __cplusplus
}
#endif

#endif /* SYMCR_TESTS_RUNTIME_C_API_TEST_STATE_H */
