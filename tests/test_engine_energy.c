#include "fs_test.h"
#include "footsim/fs_error.h"
static void nothing(void) {}
FS_TEST_MAIN(TEST(nothing))
