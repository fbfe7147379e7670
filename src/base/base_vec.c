/* base_vec.c: 3-vector helpers. */
#include "footsim/base/fs_vec.h"

#include <math.h>

fs_vec3 fs_v3(double x, double y, double z) { return (fs_vec3){x, y, z}; }
fs_vec3 fs_add(fs_vec3 a, fs_vec3 b) { return fs_v3(a.x + b.x, a.y + b.y, a.z + b.z); }
fs_vec3 fs_sub(fs_vec3 a, fs_vec3 b) { return fs_v3(a.x - b.x, a.y - b.y, a.z - b.z); }
fs_vec3 fs_scale(fs_vec3 a, double s) { return fs_v3(a.x * s, a.y * s, a.z * s); }
double fs_dot(fs_vec3 a, fs_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
fs_vec3 fs_cross(fs_vec3 a, fs_vec3 b) { return fs_v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x); }
double fs_norm(fs_vec3 a) { return sqrt(fs_dot(a, a)); }

fs_vec3 fs_rotate(fs_vec3 a, fs_vec3 u, double angle)
{
    double c = cos(angle), s = sin(angle);
    fs_vec3 along = fs_scale(u, fs_dot(u, a) * (1.0 - c));
    return fs_add(fs_add(fs_scale(a, c), fs_scale(fs_cross(u, a), s)), along);
}
