# `cmake --install`: the headers under include/pride/ (paths as in the tree, so "engine/run.hpp"
# reads the same inside and outside), the static libraries, the `pride` command, and a CMake
# package: find_package(pride) gives pride::engine, pride::experiment (campaigns), pride::storage (the store's
# reader), pride::framework, pride::algorithms, pride::problems, pride::grid, pride::bbob, pride::roughset
# (and pride::report or pride::statistics, whichever this tree has). pride_cli_lib is the command's own
# code, not a library for others: not exported.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(PRIDE_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/pride)

set(pride_exported pride_framework pride_roughset pride_bbob pride_cec pride_cec2006 pride_cec2020rw pride_bbob_constrained pride_bbob_mixint pride_continuous pride_problems pride_grid pride_algorithms
                   pride_engine pride_storage pride_experiment)
set(PRIDE_NEEDS_BOOST OFF)
foreach(t IN ITEMS pride_report pride_statistics)
  if(TARGET ${t})
    list(APPEND pride_exported ${t})
    set(PRIDE_NEEDS_BOOST ON)  # both carry Boost.Math's distributions
  endif()
endforeach()
foreach(t IN LISTS pride_exported)
  string(REPLACE "pride_" "" name ${t})
  set_target_properties(${t} PROPERTIES EXPORT_NAME ${name})
endforeach()

# pride's headers are C++20: users get the standard from the targets, whatever their own default.
target_compile_features(pride_framework INTERFACE cxx_std_20)

# The warning flags stay inside this build ($<BUILD_INTERFACE:pride_warnings>); only a sanitized
# build's runtimes follow its static libraries, since they cannot be linked without them.
if(PRIDE_SANITIZE)
  target_link_options(pride_framework INTERFACE $<INSTALL_INTERFACE:-fsanitize=address,undefined>)
endif()

install(TARGETS ${pride_exported} EXPORT prideTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS pride RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

# Headers only (engine/entries/ holds registration sources, nothing to include). The prefix is
# include/pride, as the targets' $<INSTALL_INTERFACE:include/pride> says.
install(DIRECTORY framework roughset problems algorithms engine experiment
        DESTINATION include/pride
        FILES_MATCHING PATTERN "*.hpp"
        REGEX "/engine/entries$" EXCLUDE
        REGEX "/experiment/html$" EXCLUDE  # pride_html (the report page, cairo) is the command's and Python's
        REGEX "/experiment/store.hpp$" EXCLUDE  # the campaign runner's own, not an interface
        # the campaign file reader's own (toml++)
        REGEX "/experiment/campaign/toml_(seeds|nodes|mixint).hpp$" EXCLUDE)

set(PRIDE_CONFIG_MPI OFF)  # MPI is a dependency only when pride_engine was built with it
if(PRIDE_MPI)
  set(PRIDE_CONFIG_MPI ON)
endif()
install(EXPORT prideTargets NAMESPACE pride:: DESTINATION ${PRIDE_INSTALL_CMAKEDIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/prideConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/cmake/prideConfig.cmake
                              INSTALL_DESTINATION ${PRIDE_INSTALL_CMAKEDIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/cmake/prideConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/cmake/prideConfig.cmake ${PROJECT_BINARY_DIR}/cmake/prideConfigVersion.cmake
        DESTINATION ${PRIDE_INSTALL_CMAKEDIR})
