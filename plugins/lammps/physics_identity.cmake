# cmake -DSOURCE_DIR=... -DLIST=... -DCONFIG=... -DOUTPUT=... -P physics_identity.cmake
# Writes OUTPUT (lmp_runin.physics): on its first line the SHA-256 of the lines after it, which are the build
# configuration (CONFIG: compiler, flags, the LAMMPS release and probes) and the SHA-256 of each source compiled
# into lmp_runin (LIST: paths relative to SOURCE_DIR, sorted). Neither paths of this machine nor times enter it, so
# a relink, another checkout or another build directory of the same sources gives the same identity
# (doc/homogenise.md, "Cache").
file(READ "${CONFIG}" _text)
file(STRINGS "${LIST}" _files)
foreach(_file IN LISTS _files)
  file(SHA256 "${SOURCE_DIR}/${_file}" _hash)
  string(APPEND _text "${_hash}  ${_file}\n")
endforeach()
string(SHA256 _identity "${_text}")
set(_content "${_identity}\n${_text}")
if(EXISTS "${OUTPUT}")
  file(READ "${OUTPUT}" _old)
  if(_old STREQUAL _content)
    return()
  endif()
endif()
file(WRITE "${OUTPUT}.tmp" "${_content}")
file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
