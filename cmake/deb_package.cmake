# `cpack -G DEB` in a Release build tree: one package, tubemesh_<version>_<arch>.deb, with the
# CLI, the MPI driver (when built) and the Python module under /usr. dpkg-shlibdeps reads the
# installed programs and names the runtime library packages (OpenCASCADE 7.6, oneTBB, fmt,
# Open MPI, SQLite, OpenSSL); what it cannot see is listed here.
set(CPACK_PACKAGE_NAME tubemesh)
set(CPACK_PACKAGE_CONTACT "tubemesh maintainers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Conforming hybrid meshes (hex rings, pyramids, tets) for solids with tubular holes")
string(CONCAT CPACK_PACKAGE_DESCRIPTION
    "Meshes CAD solids (STEP, IGES, BREP) with open-ended tubular holes for finite-element analysis:\n"
    "swept hexahedra around every hole, a layer of pyramids, tetrahedra elsewhere. Provides the\n"
    "tubemesh command, the tubemesh-mpi batch driver and the Python module tubemesh.")
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
if(TARGET tubemesh_python)
  # The module is built for one Python minor version and returns numpy arrays.
  math(EXPR next_minor "${TUBEMESH_PYTHON_MINOR} + 1")
  set(CPACK_DEBIAN_PACKAGE_DEPENDS "python3 (>= ${TUBEMESH_PYTHON_MAJOR}.${TUBEMESH_PYTHON_MINOR}~), \
python3 (<< ${TUBEMESH_PYTHON_MAJOR}.${next_minor}), python3-numpy")
endif()
if(TARGET tubemesh-mpi)
  set(CPACK_DEBIAN_PACKAGE_RECOMMENDS openmpi-bin)  # mpirun, to start tubemesh-mpi
endif()
include(CPack)
