#pragma once

// Everything needed to write and read checkpoint archives: the archive
// classes and the serialisation of the standard containers used in the
// state of a run.
#include <signorini/archive.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/map.hpp>
#include <boost/serialization/set.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
