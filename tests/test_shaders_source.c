// Shader sources: shaders/*.glsl are the source of truth; the header's embedded copies must equal
// them byte for byte (run `make shaders` after editing a .glsl file). Included by test_cpu_main.c.
#include <dirent.h>

static char *readWholeFile(const char *path, long *size)
{
    FILE *f = fopen(path, "rb");
    if (f == NULL) return NULL;
    fseek(f, 0, SEEK_END);
    *size = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *data = (char *)malloc((size_t)*size + 1);
    if ((data != NULL) && (fread(data, 1, (size_t)*size, f) != (size_t)*size)) { free(data); data = NULL; }
    if (data != NULL) data[*size] = '\0';
    fclose(f);
    return data;
}

static void test_shaders_embedded_copies_equal_the_glsl_files(void)
{
    int embedded = (int)(sizeof(rbl__shaderFiles)/sizeof(rbl__shaderFiles[0]));
    for (int i = 0; i < embedded; i++)
    {
        char path[256];
        snprintf(path, sizeof(path), "shaders/%s", rbl__shaderFiles[i].file);
        long size = 0;
        char *text = readWholeFile(path, &size);
        RT_CHECK(text != NULL, "%s: cannot read (run the tests from the repository root)", path);
        if (text == NULL) continue;
        char *embeddedText = rbl__joinSource("", rbl__shaderFiles[i].source);
        RT_CHECK(((long)strlen(embeddedText) == size) && (strcmp(text, embeddedText) == 0),
                 "%s differs from the copy embedded in rbillboard_lit.h: run `make shaders`", path);
        RBL_FREE(embeddedText);
        free(text);
    }
    // Every .glsl file is embedded (a new shader file without `make shaders` fails here)
    DIR *dir = opendir("shaders");
    RT_CHECK(dir != NULL, "no shaders/ directory");
    int files = 0;
    for (struct dirent *e = (dir != NULL)? readdir(dir) : NULL; e != NULL; e = readdir(dir))
    {
        size_t n = strlen(e->d_name);
        if ((n < 5) || (strcmp(e->d_name + n - 5, ".glsl") != 0)) continue;
        files++;
        bool found = false;
        for (int i = 0; i < embedded; i++) if (strcmp(rbl__shaderFiles[i].file, e->d_name) == 0) found = true;
        RT_CHECK(found, "shaders/%s is not embedded in the header: run `make shaders`", e->d_name);
    }
    if (dir != NULL) closedir(dir);
    RT_CHECK(files == embedded, "%d .glsl files, %d embedded", files, embedded);
}
