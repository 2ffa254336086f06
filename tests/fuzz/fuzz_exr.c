/* fuzz_exr.c: the libFuzzer harness of the OpenEXR reader: any bytes, then the invariants. */
#include <math.h>
#include <string.h>

#include "fuzz.h"
#include "image.h"
#include "image_read.h"

/* Nothing to prepare: the reader reads from memory. */
int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc, (void)argv;
    return 0;
}

/* Opens data (size bytes) as a stream. */
static FILE *open_bytes(const uint8_t *data, size_t size)
{
    static const char empty[1];
    FILE *f = fmemopen(size > 0 ? (void *)data : (void *)empty, size, "r");
    FUZZ_CHECK(f != NULL);
    return f;
}

/* Reads data as an OpenEXR file from memory; checks that a refusal leaves no image and says
 * why, that an image read has the size its header gives, and reads every value it holds
 * (a value from memory no decoder wrote is then an error under valgrind). */
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    FILE *f = open_bytes(data, size);
    Image img;
    Error err = {{0}};
    bool ok = image_read_exr_stream(&img, f, "fuzz.exr", &err);
    fclose(f);
    if (!ok) {
        FUZZ_CHECK(img.pixels == NULL && img.width == 0 && img.height == 0);
        FUZZ_CHECK(err.text[0] != '\0');
        return 0;
    }
    FUZZ_CHECK(image_size_ok(img.width, img.height) && img.pixels != NULL);
    long nans = 0;
    for (long k = 0; k < 3L * img.width * img.height; k++)
        nans += isnan(img.pixels[k]) ? 1 : 0;
    FUZZ_CHECK(nans <= 3L * img.width * img.height);
    f = open_bytes(data, size);
    int width, height;
    FUZZ_CHECK(image_exr_size(f, &width, &height, &err));
    FUZZ_CHECK(width == img.width && height == img.height);
    fclose(f);
    image_free(&img);
    return 0;
}
