// Unit test entry: one headless GL context for every test that needs one.
#include <gtest/gtest.h>

#include "gl/context.h"

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  int rc = RUN_ALL_TESTS();
  sn::gl::destroy_current();
  return rc;
}
