/* render_example.c: a program built against the installed renderer library (pkg-config footsim-render);
 * it writes a 2x2 PNG through it and reads it back (no OSMesa needed). Usage: render_example FILE */
#include "footsim/render/fs_render.h"

#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
    if (argc != 2)
        return 2;
    const unsigned char rgba[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
    fs_error err;
    unsigned char *back = NULL;
    int w = 0, h = 0;
    if (fs_render_png_write(argv[1], rgba, 2, 2, 8, 0, 6, &err) != FS_OK ||
        fs_render_png_read(argv[1], &back, &w, &h, &err) != FS_OK) {
        fprintf(stderr, "render_example: %s\n", err.message);
        return err.status;
    }
    int same = w == 2 && h == 2;
    for (int i = 0; same && i < 16; i++)
        same = back[i] == rgba[i];
    free(back);
    printf("%dx%d PNG written and read back: %s\n", w, h, same ? "same" : "DIFFERENT");
    return same ? 0 : 1;
}
