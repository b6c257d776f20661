#include <impact_fem/postprocess/interface.h>

namespace impact_fem
{
  namespace postprocess
  {
    void
    declare_parameters(ParameterHandler &prm)
    {
      for (const auto &kind : Registry<Interface>::all())
        kind.second.declare_parameters(prm);
    }


    std::vector<std::pair<std::string, std::unique_ptr<Interface>>>
    create_postprocessors(ParameterHandler &prm)
    {
      std::vector<std::pair<std::string, std::unique_ptr<Interface>>> all;
      for (const auto &[name, kind] : Registry<Interface>::all())
        {
          all.emplace_back(name, kind.create());
          all.back().second->parse_parameters(prm);
        }
      return all;
    }
  } // namespace postprocess
} // namespace impact_fem
