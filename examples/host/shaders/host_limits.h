// Numbers the host example's C++ and its shaders share, defined once (plain #defines, read by both).
#ifndef HOST_LIMITS_H
#define HOST_LIMITS_H
// The most vertices the scene pass's uniform buffer holds: scene.vert's HostVertices array.
#define HOST_MAX_VERTICES 256
#endif
