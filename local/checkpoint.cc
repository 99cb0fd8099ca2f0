#include "checkpoint.h"

#include <hdf5.h>

#include <cstdio>
#include <stdexcept>
#include <vector>

#include "hdf5_array.h"

namespace pumpd::local
{
  namespace
  {
    void fail_if(bool bad, const std::string &what)
    {
      if (bad)
        throw std::runtime_error("checkpoint: " + what);
    }

    template <class T>
    void write_array(hid_t file, const char *name, const std::vector<T> &v)
    {
      hdf5::write_array(file, name, v, "checkpoint");
    }

    template <class T>
    void read_array(hid_t file, const char *name, std::vector<T> &v, std::size_t expected)
    {
      v = hdf5::read_array<T>(file, name, "checkpoint", expected);
    }

    void write_scalar(hid_t object, const std::string &name, double value)
    {
      const hid_t space = H5Screate(H5S_SCALAR);
      const hid_t attr  = H5Acreate2(object, name.c_str(), H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT);
      fail_if(attr < 0 || H5Awrite(attr, H5T_NATIVE_DOUBLE, &value) < 0, "cannot write " + name);
      H5Aclose(attr);
      H5Sclose(space);
    }

    double read_scalar(hid_t object, const std::string &name)
    {
      const hid_t attr = H5Aopen(object, name.c_str(), H5P_DEFAULT);
      fail_if(attr < 0, "no attribute " + name);
      double value = 0.;
      fail_if(H5Aread(attr, H5T_NATIVE_DOUBLE, &value) < 0, "cannot read " + name);
      H5Aclose(attr);
      return value;
    }

    herr_t collect(hid_t object, const char *name, const H5A_info_t *, void *data)
    {
      (*static_cast<Attributes *>(data))[name] = read_scalar(object, name);
      return 0;
    }

    /// Sizes that must match between the model that wrote a checkpoint and the one reading it.
    Attributes shape(const PdModel &model)
    {
      const auto &l = model.lattice();
      return {{"lattice_nx", double(l.nx())},
              {"lattice_ny", double(l.ny())},
              {"lattice_spacing", l.spacing()},
              {"horizon_ratio", double(l.reach())},
              {"stencil_size", double(model.stencil().size())}};
    }
  } // namespace

  void write_checkpoint(const std::string &path, const PdModel &model, const State &s,
                        const Attributes &attributes)
  {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    const std::string tmp  = path + ".tmp";
    const hid_t       file = H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    fail_if(file < 0, "cannot create " + tmp);
    write_array(file, "ux", s.ux);
    write_array(file, "uy", s.uy);
    write_array(file, "vx", s.vx);
    write_array(file, "vy", s.vy);
    write_array(file, "fx", s.fx);
    write_array(file, "fy", s.fy);
    write_array(file, "broken_bonds", s.broken);
    for (const auto &[name, value] : shape(model))
      write_scalar(file, name, value);
    write_scalar(file, "time", s.time);
    write_scalar(file, "step", double(s.step));
    write_scalar(file, "dissipated", s.dissipated);
    write_scalar(file, "external_work", s.external_work);
    const hid_t driver = H5Gcreate2(file, "driver", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    for (const auto &[name, value] : attributes)
      write_scalar(driver, name, value);
    H5Gclose(driver);
    fail_if(H5Fclose(file) < 0, "cannot close " + tmp);
    // Replace the previous checkpoint only once the new one is complete.
    fail_if(std::rename(tmp.c_str(), path.c_str()) != 0, "cannot move " + tmp + " to " + path);
  }

  State read_checkpoint(const std::string &path, const PdModel &model, Attributes *attributes)
  {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    fail_if(file < 0, "cannot open " + path);
    try
      {
        for (const auto &[name, value] : shape(model))
          fail_if(read_scalar(file, name) != value,
                  path + " was written for another lattice (" + name + " differs)");
        State             s = model.initial_state();
        const std::size_t n = s.ux.size();
        read_array(file, "ux", s.ux, n);
        read_array(file, "uy", s.uy, n);
        read_array(file, "vx", s.vx, n);
        read_array(file, "vy", s.vy, n);
        read_array(file, "fx", s.fx, n);
        read_array(file, "fy", s.fy, n);
        read_array(file, "broken_bonds", s.broken, s.broken.size());
        s.time          = read_scalar(file, "time");
        s.step          = std::uint64_t(read_scalar(file, "step"));
        s.dissipated    = read_scalar(file, "dissipated");
        s.external_work = read_scalar(file, "external_work");
        if (attributes)
          {
            const hid_t driver = H5Gopen2(file, "driver", H5P_DEFAULT);
            fail_if(driver < 0, "no driver group in " + path);
            hsize_t index = 0;
            H5Aiterate2(driver, H5_INDEX_NAME, H5_ITER_INC, &index, collect, attributes);
            H5Gclose(driver);
          }
        H5Fclose(file);
        return s;
      }
    catch (...)
      {
        H5Fclose(file);
        throw;
      }
  }
} // namespace pumpd::local
