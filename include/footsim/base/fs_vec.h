/* fs_vec.h: small 3-vector helpers used by the model and the analyses (doubles, z up). */
#ifndef FS_VEC_H
#define FS_VEC_H

typedef struct fs_vec3 { double x, y, z; } fs_vec3;

fs_vec3 fs_v3(double x, double y, double z);
fs_vec3 fs_add(fs_vec3 a, fs_vec3 b);
fs_vec3 fs_sub(fs_vec3 a, fs_vec3 b);
fs_vec3 fs_scale(fs_vec3 a, double s);
double fs_dot(fs_vec3 a, fs_vec3 b);
fs_vec3 fs_cross(fs_vec3 a, fs_vec3 b);
double fs_norm(fs_vec3 a);
/* a rotated by angle (rad) about the unit axis u (Rodrigues). */
fs_vec3 fs_rotate(fs_vec3 a, fs_vec3 u, double angle);

#endif
