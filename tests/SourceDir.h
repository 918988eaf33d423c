#pragma once
// Where the source tree is, for tests that read models/ and tests/testdata/.
// The test targets define MILLDYN_SOURCE_DIR as a call of this function and
// force-include this header (cmake: milldyn_test_source_dir), so only
// tests/SourceDir.cpp is compiled with the path: every other test file's
// compile line is the same in any checkout, and a compiler cache shared by
// several checkouts serves them all.

namespace milldyn::test {
const char* sourceDir();
}  // namespace milldyn::test
