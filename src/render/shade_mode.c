/*
 * shade_mode.c - the names of the shading modes, as the command line
 * (--shade) and scene files (shade ...) spell them.  Nothing here shades.
 */
#include <string.h>

#include "rayo/render.h"

static const char *const mode_names[] = {"hit", "course-gray",
                                         "course-color", "phong",
                                         "course-tp1"};
#define MODE_COUNT (sizeof mode_names / sizeof mode_names[0])

rayo_status rayo_shade_mode_parse(const char *name, rayo_shade_mode *mode,
                                  rayo_error *err)
{
    size_t i;
    for (i = 0; i < MODE_COUNT; i++) {
        if (strcmp(name, mode_names[i]) == 0) {
            *mode = (rayo_shade_mode)i;
            return RAYO_OK;
        }
    }
    return rayo_error_set(err, RAYO_ERR_INVALID,
                          "shading mode '%s' is not known; expected hit, "
                          "course-gray, course-color, phong or course-tp1",
                          name);
}

const char *rayo_shade_mode_name(rayo_shade_mode mode)
{
    if ((size_t)mode < MODE_COUNT)
        return mode_names[mode];
    return "unknown";
}
