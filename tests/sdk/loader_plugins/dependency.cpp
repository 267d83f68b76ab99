// The dependency that missing_dependency.cpp cannot find at load time.
extern "C" __attribute__((visibility("default"))) double paddy_loader_test_dependency_value() { return 1.0; }
