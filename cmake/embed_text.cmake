# Writes a text file into C++ as a string: cmake -DIN=file -DOUT=file.inc -DNAME=kName -P this.
# The .inc holds `constexpr std::string_view NAME = R"fogdrift_embed(...)fogdrift_embed";`, the
# file's bytes as they are (src/stream/step.h into c_streaming.cpp).
file(READ "${IN}" text)
string(FIND "${text}" ")fogdrift_embed\"" clash)
if(NOT clash EQUAL -1)
  message(FATAL_ERROR "${IN} holds the raw string's end marker")
endif()
file(WRITE "${OUT}.tmp"
     "// Generated from ${IN} by cmake/embed_text.cmake; do not edit.\n"
     "constexpr std::string_view ${NAME} = R\"fogdrift_embed(${text})fogdrift_embed\";\n")
file(RENAME "${OUT}.tmp" "${OUT}")
