# Precompiled headers for the targets with many sources. A Stoa source spends
# most of its compile time parsing the standard library and GLM (MeshObject.cpp:
# 85 % of 2.5 s in parsing), so each big target parses them once, into a PCH that
# its sources share. STOA_PRECOMPILED_HEADERS=OFF turns it off (to check that
# every file includes what it uses).
option(STOA_PRECOMPILED_HEADERS "Precompile the standard library and GLM headers for the big targets" ON)

set(STOA_PRECOMPILED
  <algorithm> <cmath> <cstdint> <cstdio> <cstdlib> <cstring> <filesystem> <fstream> <functional>
  <map> <memory> <optional> <set> <sstream> <stdexcept> <string> <unordered_map> <utility> <vector>
  <glm/glm.hpp> <glm/gtc/matrix_transform.hpp> <glm/gtc/type_ptr.hpp>)

# stoa_precompile_headers(TARGET [HEADERS...]): the common set plus HEADERS.
function(stoa_precompile_headers target)
  if(NOT STOA_PRECOMPILED_HEADERS OR CMAKE_VERSION VERSION_LESS 3.16)
    return()
  endif()
  target_precompile_headers(${target} PRIVATE ${STOA_PRECOMPILED} ${ARGN})
endfunction()
