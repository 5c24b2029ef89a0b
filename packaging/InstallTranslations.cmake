# Installs the compiled translations (install script of packaging/CMakeLists.txt): for every
# translations/armtrack_<lang>.ts, the armtrack_<lang>.qm that qt_add_translations made somewhere
# in the build tree. A shipped .ts without its .qm stops the install, so a package never lacks a
# language silently. Set by the caller: ARMTRACK_BINARY_DIR, ARMTRACK_TS_FILES (names),
# ARMTRACK_QM_DESTINATION (relative to the prefix).
file(GLOB_RECURSE all_qm LIST_DIRECTORIES false "${ARMTRACK_BINARY_DIR}/armtrack_*.qm")
# Not the copies in CPack's staging tree or in the install test's root.
list(FILTER all_qm EXCLUDE REGEX "/_CPack_Packages/|/install-test/")
foreach(ts IN LISTS ARMTRACK_TS_FILES)
  string(REGEX REPLACE "\\.ts$" ".qm" qm "${ts}")
  set(found "${all_qm}")
  list(FILTER found INCLUDE REGEX "/${qm}$")
  list(FILTER all_qm EXCLUDE REGEX "/${qm}$")
  list(LENGTH found n)
  if(NOT n EQUAL 1)
    message(FATAL_ERROR "translations/${ts}: expected one ${qm} in the build tree, found ${n} "
      "(${found}); build the GUI (qt_add_translations) first")
  endif()
  file(INSTALL ${found} DESTINATION "${CMAKE_INSTALL_PREFIX}/${ARMTRACK_QM_DESTINATION}")
endforeach()
if(all_qm)
  message(WARNING "not installed, no translations/*.ts of that name: ${all_qm}")
endif()
