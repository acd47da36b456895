// v1: one array grows, one shrinks, the grid gains a row and a column.
#include <cstring>

#include "check.hpp"

struct Tables {
  int grows[5];
  int shrinks[3];
  short grid[3][4];
  char name[8];
};

SYMCR_CHECKPOINT Tables tables;

int main(int argc, char** argv) {
  tables = {{-1, -1, -1, -1, -1}, {-1, -1, -1}, {{-1, -1, -1, -1}, {-1, -1, -1, -1},
                                                 {-1, -1, -1, -1}}, ""};
  symcr::Report report = xv::restore(argc, argv);
  XV_CHECK(report.ok());
  XV_CHECK(tables.grows[0] == 1 && tables.grows[1] == 2 && tables.grows[2] == 3);
  XV_CHECK(tables.grows[3] == -1 && tables.grows[4] == -1);
  XV_CHECK(tables.shrinks[0] == 10 && tables.shrinks[1] == 20 && tables.shrinks[2] == 30);
  XV_CHECK(tables.grid[0][0] == 1 && tables.grid[0][2] == 3 && tables.grid[1][2] == 6);
  XV_CHECK(tables.grid[0][3] == -1 && tables.grid[2][0] == -1);
  XV_CHECK(std::strcmp(tables.name, "copter") == 0);
  XV_CHECK(xv::decided(report, "tables.grows", symcr::Decision::Converted));
  XV_CHECK(xv::decided(report, "tables.shrinks", symcr::Decision::Converted));
  return xv::verdict();
}
