/*
 * course.h - the course's room in one include: the registry of its
 * exercises, their mistakes and images (course/course.h) and their
 * scenes' numbers and maps (course/course_scene.h).  Kept so that
 * existing users of "rayo/course.h" compile unchanged; nothing is
 * declared here.
 */
#ifndef RAYO_COURSE_H
#define RAYO_COURSE_H

#include "rayo/course/course.h"
#include "rayo/course/course_scene.h"

#endif
