# Run at install time (install(CODE) in the top CMakeLists.txt), where CMAKE_INSTALL_PREFIX is the
# prefix of `cmake --install build --prefix P`, so that the unit file and the configuration follow
# the prefix given then, not only the one configured. The absolute directories follow
# GNUInstallDirs: prefix /usr -> /etc; /opt/NAME -> /etc/opt/NAME; else PREFIX/etc.
# In: RIG_SOURCE_DIR, RIG_BINARY_DIR, RIG_BINDIR_REL, RIG_SYSCONFDIR_REL, RIG_DOCDIR_REL.

function(rig_full_dir out rel is_etc)
  if(IS_ABSOLUTE "${rel}")
    set(dir "${rel}")
  elseif(is_etc AND CMAKE_INSTALL_PREFIX MATCHES "^/usr/?$")
    set(dir "/${rel}")
  elseif(is_etc AND CMAKE_INSTALL_PREFIX MATCHES "^/opt/" AND NOT CMAKE_INSTALL_PREFIX MATCHES "^/opt/homebrew/")
    string(REGEX REPLACE "/$" "" prefix "${CMAKE_INSTALL_PREFIX}")
    set(dir "/${rel}${prefix}")
  else()
    string(REGEX REPLACE "/$" "" prefix "${CMAKE_INSTALL_PREFIX}")
    set(dir "${prefix}/${rel}")
  endif()
  set(${out} "${dir}" PARENT_SCOPE)
endfunction()

rig_full_dir(RIG_BINDIR "${RIG_BINDIR_REL}" FALSE)
rig_full_dir(RIG_SYSCONFDIR "${RIG_SYSCONFDIR_REL}" TRUE)
rig_full_dir(RIG_DOCDIR "${RIG_DOCDIR_REL}" FALSE)
