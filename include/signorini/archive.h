#pragma once

// The archives of checkpoints (driver/checkpoint.h): each part of a run
// that has state saves and loads it through these, in its own
// save_state() / load_state(). Declared here so that interfaces need not
// include Boost.Serialization; the source files that write or read an
// archive include signorini/archive_io.h.
namespace boost
{
  namespace archive
  {
    class binary_oarchive;
    class binary_iarchive;
  } // namespace archive
} // namespace boost

namespace Signorini
{
  using OutputArchive = boost::archive::binary_oarchive;
  using InputArchive  = boost::archive::binary_iarchive;
} // namespace Signorini
