# The Make build of either version of the rover (rover_v0/Makefile, rover_v1/Makefile include
# it): sources in SRC, everything built in BUILD, dependencies tracked through the compiler's
# depfiles. symcr enters only through CXX="symcr-c++ g++".
SRC ?= .
BUILD ?= build
CXX ?= g++
CXXFLAGS ?= -O2 -std=c++17 -Wall
AR ?= ar

objects := $(BUILD)/src/main.o $(BUILD)/src/util.o

$(BUILD)/rover: $(objects) $(BUILD)/librover.a
	$(CXX) -o $@ $(objects) -L$(BUILD) -lrover

$(BUILD)/librover.a: $(BUILD)/lib/rover.o
	rm -f $@
	$(AR) rcs $@ $^

$(BUILD)/%.o: $(SRC)/%.cpp
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS) -I$(SRC)/include -MMD -MP -c $< -o $@

-include $(objects:.o=.d) $(BUILD)/lib/rover.d
