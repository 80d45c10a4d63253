/* Hostile: an initialised array of 1.9 GB: the object file and the
   program are that big, written by the assembler and the linker (the
   compile step, unbounded, fills the host's disk). */
char big[1900000000] = {1};

int main(void)
{
    return big[1899999999];
}
