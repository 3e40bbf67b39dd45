// Anchor translation unit of the test-support library (the oracles live beside it).
namespace rearm::test_support {}
