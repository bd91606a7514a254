// SPDX-License-Identifier: BSD-3-Clause
#include "jobs/MethodsJob.h"

#include <nlohmann/json.hpp>

#include "transforms/Methods.h"

namespace bandlight::jobs
{

namespace
{
/// The name the entry's description is given for: its first default, else
/// the first name of its syntax.
std::string FirstName(const MethodEntry& e)
{
    for (const auto* list : {&e.configDefaults, &e.accuracyDefaults, &e.cameraDefaults})
    {
        if (!list->empty())
        {
            return list->front();
        }
    }
    const std::string syntax = e.syntax;
    return syntax.substr(0, syntax.find(','));
}
}  // namespace

std::vector<MethodInfo> ListMethods()
{
    std::vector<MethodInfo> out;
    for (const MethodEntry& e : Methods())
    {
        MethodInfo m;
        m.names = e.syntax;
        m.exactness = MethodExactnessName(e.exactness);
        m.native = e.native;
        m.needsCamera = e.needsCamera;
        m.takesTraining = e.takesTraining;
        m.trainingSize = e.defaultTraining ? e.defaultTraining().size() : 0;
        if (!e.configDefaults.empty())
        {
            m.defaultIn.push_back("config");
        }
        if (!e.accuracyDefaults.empty())
        {
            m.defaultIn.push_back("accuracy");
        }
        if (!e.cameraDefaults.empty())
        {
            m.defaultIn.push_back("camera accuracy");
        }
        m.description = DescribeMethod(ParseMethod(FirstName(e)));
        out.push_back(m);
    }
    return out;
}

std::string MethodsDocument(const std::vector<MethodInfo>& methods)
{
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const MethodInfo& m : methods)
    {
        nlohmann::ordered_json j;
        j["names"] = m.names;
        j["exactness"] = m.exactness;
        j["native"] = m.native;
        j["needs_camera"] = m.needsCamera;
        j["takes_training"] = m.takesTraining;
        j["training_size"] = m.trainingSize;
        j["default_in"] = m.defaultIn;
        j["description"] = m.description;
        list.push_back(j);
    }
    return list.dump(2);
}

}  // namespace bandlight::jobs
