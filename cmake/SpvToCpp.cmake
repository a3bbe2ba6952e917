# Turns one SPIR-V file into a C++ byte array (run in script mode by EmbedShaders.cmake).
file(READ ${SPV} hex HEX)
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," bytes "${hex}")
file(SIZE ${SPV} size)
file(WRITE ${OUT} "extern const unsigned char ${IDENT}[] = {${bytes}};\nextern const unsigned long ${IDENT}_size = ${size};\n")
