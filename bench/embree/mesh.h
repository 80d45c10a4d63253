/*
 * mesh.h - the Embree program's triangle meshes (mesh.c): a scene's binary
 * STL files read into scene.corners, and given to Embree as one triangle
 * geometry sharing that array.
 */
#ifndef EMBREE_RAYS_MESH_H
#define EMBREE_RAYS_MESH_H

#include <embree3/rtcore.h>

#include "scene.h"

/* Appends the triangles of the binary STL at path to s (exits on bad
 * input, 2, or an I/O failure, 1, with one line on stderr). */
void read_mesh(const char *path, scene *s);

/* The scene's triangles as one geometry of es (none: nothing). */
void attach_meshes(RTCDevice device, RTCScene es, const scene *s);

#endif
