# Install-time step of the default component: the unit generated for the install prefix and the
# configuration in SYSCONFDIR/rig, the bench configuration as its rig.toml (the service runs it).
include("${CMAKE_CURRENT_LIST_DIR}/install_paths.cmake")

configure_file("${RIG_SOURCE_DIR}/systemd/rig.service.in" "${RIG_BINARY_DIR}/systemd/rig.service"
               @ONLY)
file(INSTALL DESTINATION "${CMAKE_INSTALL_PREFIX}/lib/systemd/system" TYPE FILE
     FILES "${RIG_BINARY_DIR}/systemd/rig.service")
file(INSTALL DESTINATION "${RIG_SYSCONFDIR}/rig" TYPE DIRECTORY FILES "${RIG_SOURCE_DIR}/config/"
     PATTERN "rig.toml" EXCLUDE)
# The 20 s demo (config/rig.toml) beside it as demo.toml; bench.toml stays under its own name too.
file(INSTALL DESTINATION "${RIG_SYSCONFDIR}/rig" TYPE FILE
     FILES "${RIG_SOURCE_DIR}/config/bench.toml" RENAME rig.toml)
file(INSTALL DESTINATION "${RIG_SYSCONFDIR}/rig" TYPE FILE
     FILES "${RIG_SOURCE_DIR}/config/rig.toml" RENAME demo.toml)
