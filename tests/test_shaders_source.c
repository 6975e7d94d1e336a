// Shader sources: shaders/*.glsl are the source of truth; the header's embedded copies must equal
// them byte for byte, and each stage's part list must be the closure of its #include lines,
// dependencies first (run `make shaders` after editing a .glsl file). Included by test_cpu_main.c.
#include <dirent.h>

// The embedded lines of one file joined back into its text (malloc'd)
static char *joinLines(const char *const *lines)
{
    size_t len = 0;
    for (int i = 0; lines[i] != NULL; i++) len += strlen(lines[i]);
    char *text = (char *)malloc(len + 1);
    if (text == NULL) return NULL;
    text[0] = '\0';
    for (int i = 0; lines[i] != NULL; i++) strcat(text, lines[i]);
    return text;
}

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
        char *embeddedText = joinLines(rbl__shaderFiles[i].source);
        RT_CHECK(((long)strlen(embeddedText) == size) && (strcmp(text, embeddedText) == 0),
                 "%s differs from the copy embedded in rbillboard_lit.h: run `make shaders`", path);
        free(embeddedText);
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

// Embedded file index of a shader file name, or -1
static int shaderIndex(const char *file)
{
    for (int i = 0; i < (int)(sizeof(rbl__shaderFiles)/sizeof(rbl__shaderFiles[0])); i++) if (strcmp(rbl__shaderFiles[i].file, file) == 0) return i;
    return -1;
}

// Depth-first include closure of file (read from shaders/), dependencies first, each file once
static void includeClosure(const char *file, int order[64], int *count)
{
    int self = shaderIndex(file);
    RT_CHECK(self >= 0, "%s is included but not embedded", file);
    if (self < 0) return;
    for (int k = 0; k < *count; k++) if (order[k] == self) return;
    char path[256];
    snprintf(path, sizeof(path), "shaders/%s", file);
    long size = 0;
    char *text = readWholeFile(path, &size);
    RT_CHECK(text != NULL, "%s: cannot read", path);
    for (char *line = text; (line != NULL) && (*line != '\0'); )
    {
        char *next = strchr(line, '\n');
        char name[128];
        if ((strncmp(line, "#include \"", 10) == 0) && (sscanf(line + 10, "%127[^\"]", name) == 1)) includeClosure(name, order, count);
        line = (next != NULL)? next + 1 : NULL;
    }
    free(text);
    if (*count < 64) order[(*count)++] = self;
}

static void test_shaders_each_stage_lists_its_include_closure_dependencies_first(void)
{
    int stages = (int)(sizeof(rbl__passFiles)/sizeof(rbl__passFiles[0]));
    RT_CHECK(stages >= 10, "only %d stages embedded", stages);
    for (int p = 0; p < stages; p++)
    {
        int order[64], count = 0;
        includeClosure(rbl__passFiles[p].file, order, &count);
        int n = 0;
        while (rbl__passFiles[p].parts[n] != NULL) n++;
        bool same = (n == count);
        for (int k = 0; same && (k < n); k++) same = (rbl__passFiles[p].parts[k] == rbl__shaderFiles[order[k]].source);
        RT_CHECK(same, "%s: embedded parts (%d) are not its include closure (%d): run `make shaders`", rbl__passFiles[p].file, n, count);
        // Every part is included once and the stage itself comes last
        RT_CHECK((n > 0) && (rbl__passFiles[p].parts[n - 1] == rbl__shaderFiles[shaderIndex(rbl__passFiles[p].file)].source), "%s is not its own last part", rbl__passFiles[p].file);
    }
}
