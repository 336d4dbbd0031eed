// The host's own engine library, named `engine` like nothing of ours.
int host_engine_version() { return 1; }
