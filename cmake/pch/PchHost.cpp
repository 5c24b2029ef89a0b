// The host of a precompiled header (app/gui/CMakeLists.txt): compiling it builds the header
// that the GUI libraries reuse. It defines nothing.
