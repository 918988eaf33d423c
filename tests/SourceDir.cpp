#include "tests/SourceDir.h"

const char* milldyn::test::sourceDir() { return MILLDYN_SOURCE_DIR_PATH; }
