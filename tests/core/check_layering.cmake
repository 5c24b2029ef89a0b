# The layer rule of docs/architecture.md, checked on the sources' #include lines. ROOT is the
# source tree. Fails (FATAL_ERROR, listing every offending line) when
# - a file under core/, outside the service folders, includes a Qt or VTK header, or an OpenCV
#   header outside core/camera/*.cpp (OpenCV is private to the camera model, never in a header),
#   or a header of a core service (core/session/, core/storage/, core/reports/);
# - a core service (core/session/, core/storage/, core/reports/) includes widgets, Qt Charts or VTK (Qt Core, Sql and Gui are
#   allowed there);
# - anything under core/ includes a header of devices/, app/ or ui/ (an upward arrow);
# - anything under devices/ includes a header of app/ or ui/, or widgets;
# - anything under ui/ includes a header of app/ or of a device plugin's folder (devices/api/ is
#   allowed: ui/ sees devices through their interface);
# - a file under core/, devices/ or ui/ includes with a "../" path, which would hide such an arrow.
# - in the GUI (app/gui/), a screen folder (signin, patients, review, newsession, live, home, admin)
#   includes another screen folder or the shell (app/gui/*.h); common/ includes a screen folder
#   or the shell; services/ includes anything of app/gui/ but services/, or widgets.
# core/exports (export writers, target armtrack_exports) is science for this rule: Qt-free, and it
# must not include a service header, so the CLI, the services and the GUI can all link it.
cmake_policy(SET CMP0054 NEW)
set(include_re "^[ \t]*#[ \t]*include[ \t]*[<\"]")
set(widgets_re "${include_re}(QtWidgets|QtCharts|Q[A-Za-z]*(Widget|Dialog|Chart)|QApplication|QMainWindow|QMessageBox|vtk)")
set(services "session" "storage" "reports")

set(offenders "")
# check(<file> <regex> <why>): appends every line of file matching regex to offenders.
function(check file regex why)
  file(STRINGS "${file}" hits REGEX "${regex}")
  foreach(hit IN LISTS hits)
    string(STRIP "${hit}" hit)
    list(APPEND offenders "${file}: ${hit}  (${why})")
  endforeach()
  set(offenders "${offenders}" PARENT_SCOPE)
endfunction()

file(GLOB_RECURSE core_files "${ROOT}/core/*.h" "${ROOT}/core/*.cpp")
file(GLOB_RECURSE device_files "${ROOT}/devices/*.h" "${ROOT}/devices/*.cpp")
list(LENGTH core_files n_core)
list(LENGTH device_files n_devices)
if(n_core EQUAL 0 OR n_devices EQUAL 0)
  message(FATAL_ERROR "no sources found under ${ROOT}/core or ${ROOT}/devices")
endif()

string(JOIN "|" services_alt ${services})
foreach(f IN LISTS core_files)
  file(RELATIVE_PATH rel "${ROOT}/core" "${f}")
  if(rel MATCHES "^(${services_alt})/")
    check("${f}" "${widgets_re}" "a core service uses Qt Core, Sql and Gui, never widgets or VTK")
  else()
    check("${f}" "${include_re}(Q[A-Za-z]|vtk)" "core science is Qt- and VTK-free")
    check("${f}" "${include_re}core/(${services_alt})/" "core science must not use a Qt service")
    if(NOT rel MATCHES "^camera/.*\\.cpp$")
      check("${f}" "${include_re}opencv" "OpenCV only in core/camera/*.cpp")
    endif()
  endif()
  check("${f}" "${include_re}(devices|app|ui)/" "core/ must not include a higher layer")
  check("${f}" "${include_re}[^>\"]*\\.\\./" "relative includes hide the layer")
endforeach()

foreach(f IN LISTS device_files)
  check("${f}" "${include_re}(app|ui)/" "devices/ must not include app/ or ui/")
  check("${f}" "${widgets_re}" "a device never opens a widget or dialog")
  check("${f}" "${include_re}[^>\"]*\\.\\./" "relative includes hide the layer")
endforeach()

file(GLOB_RECURSE ui_files "${ROOT}/ui/*.h" "${ROOT}/ui/*.cpp")
foreach(f IN LISTS ui_files)
  check("${f}" "${include_re}app/" "ui/ must not include app/")
  check("${f}" "${include_re}devices/([^a/][^/]*|a[^p/][^/]*|ap[^i/][^/]*|api[^/]+)/"
    "ui/ sees devices through devices/api only")
  check("${f}" "${include_re}[^>\"]*\\.\\./" "relative includes hide the layer")
endforeach()

set(screens "signin" "patients" "review" "newsession" "live" "home" "admin")
file(GLOB gui_shell_files RELATIVE "${ROOT}/app/gui" "${ROOT}/app/gui/*.h")
list(LENGTH gui_shell_files n_shell)
if(n_shell EQUAL 0)
  message(FATAL_ERROR "no shell headers found under ${ROOT}/app/gui")
endif()
set(gui_shell_re "${include_re}app/gui/[^/\"]+\\.h")
set(n_gui 0)
foreach(screen IN LISTS screens ITEMS common services)
  file(GLOB_RECURSE files "${ROOT}/app/gui/${screen}/*.h" "${ROOT}/app/gui/${screen}/*.cpp")
  if(NOT files)
    message(FATAL_ERROR "no sources found under ${ROOT}/app/gui/${screen}")
  endif()
  list(LENGTH files n)
  math(EXPR n_gui "${n_gui} + ${n}")
  set(others ${screens})
  list(REMOVE_ITEM others ${screen})
  string(JOIN "|" others_alt ${others})
  foreach(f IN LISTS files)
    check("${f}" "${include_re}app/gui/(${others_alt})/" "no GUI screen folder includes another")
    check("${f}" "${gui_shell_re}" "the shell composes the screens, never the reverse")
    check("${f}" "${include_re}[^>\"]*\\.\\./" "relative includes hide the layer")
    if(screen STREQUAL "services")
      check("${f}" "${include_re}app/gui/(common)/" "services/ are below the widgets")
      check("${f}" "${widgets_re}" "GUI services have no widgets")
    endif()
  endforeach()
endforeach()

if(offenders)
  list(JOIN offenders "\n" text)
  message(FATAL_ERROR "layer rule broken (docs/architecture.md):\n${text}")
endif()
list(LENGTH ui_files n_ui)
message(STATUS "checked ${n_core} core, ${n_devices} device, ${n_ui} ui and ${n_gui} GUI screen files: the layers point one way")
