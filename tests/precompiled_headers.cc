// psmpm: the object that carries tests/precompiled_headers.h (see there).
