// Anchor of the test programs' precompiled header (tests/CMakeLists.txt, rearm_test_pch).
namespace rearm::test_support {}
