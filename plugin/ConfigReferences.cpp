// SPDX-License-Identifier: BSD-3-Clause
#include "plugin/ConfigReferences.h"

#include <algorithm>
#include <map>
#include <set>
#include <vector>

#include "spectral/Exception.h"

namespace bandlight
{

namespace
{

/// A node of the reference graph: what kind of config element, and its name.
struct Node
{
    enum Kind
    {
        COLOR_SPACE,
        LOOK,
        NAMED_TRANSFORM,
        VIEW_TRANSFORM,
        VIEW,
    } kind;
    std::string name;

    bool operator<(const Node& o) const { return kind != o.kind ? kind < o.kind : name < o.name; }
    std::string describe() const
    {
        static const char* kinds[] = {"colour space", "look", "named transform", "view transform",
                                      "view"};
        return std::string(kinds[kind]) + " '" + OneLine(name, 200) + "'";
    }
};

class Graph
{
public:
    explicit Graph(const OCIO::ConstConfigRcPtr& config) : m_config(config) { build(); }

    /// The first cycle found, as the path that closes it; empty if none.
    std::vector<Node> findCycle() const
    {
        std::map<Node, int> state;  // 0 new, 1 on the path, 2 done
        std::vector<Node> path;
        for (const auto& entry : m_edges)
        {
            if (state[entry.first] == 0)
            {
                if (visit(entry.first, state, path))
                {
                    return path;
                }
            }
        }
        return {};
    }

private:
    bool visit(const Node& n, std::map<Node, int>& state, std::vector<Node>& path) const
    {
        // Iterative depth-first search: a hostile config may hold long chains.
        struct Frame
        {
            Node node;
            size_t next;
        };
        std::vector<Frame> stack{{n, 0}};
        state[n] = 1;
        path = {n};
        while (!stack.empty())
        {
            Frame& f = stack.back();
            const auto it = m_edges.find(f.node);
            if (it != m_edges.end() && f.next < it->second.size())
            {
                const Node to = it->second[f.next++];
                const int s = state[to];
                if (s == 1)
                {
                    // Keep the cycle only: from the first occurrence of `to`.
                    size_t start = 0;
                    while (start < path.size() && (path[start] < to || to < path[start]))
                    {
                        ++start;
                    }
                    path.erase(path.begin(), path.begin() + long(start));
                    path.push_back(to);
                    return true;
                }
                if (s == 0)
                {
                    state[to] = 1;
                    path.push_back(to);
                    stack.push_back({to, 0});
                }
            }
            else
            {
                state[f.node] = 2;
                path.pop_back();
                stack.pop_back();
            }
        }
        return false;
    }

    /// A colour space by any of its names (role, alias), as its canonical name.
    Node space(const char* name) const
    {
        std::string n = name ? name : "";
        if (OCIO::ConstColorSpaceRcPtr cs = m_config->getColorSpace(n.c_str()))
        {
            n = cs->getName();
        }
        return {Node::COLOR_SPACE, n};
    }

    void add(const Node& from, const Node& to) { m_edges[from].push_back(to); }

    void addLooks(const Node& from, const char* looks)
    {
        // "+a, -b" / "a|b": names separated by commas or bars, with +/- prefixes.
        std::string current;
        const std::string text = looks ? looks : "";
        for (size_t i = 0; i <= text.size(); ++i)
        {
            const char c = i < text.size() ? text[i] : ',';
            if (c == ',' || c == '|' || c == ':')
            {
                const size_t a = current.find_first_not_of(" \t+-");
                const size_t b = current.find_last_not_of(" \t");
                if (a != std::string::npos)
                {
                    add(from, {Node::LOOK, current.substr(a, b - a + 1)});
                }
                current.clear();
            }
            else
            {
                current += c;
            }
        }
    }

    void addView(const Node& from, const char* display, const char* view)
    {
        add(from, {Node::VIEW, std::string(display ? display : "") + "/" + (view ? view : "")});
    }

    /// Edges from `from` to everything `t` refers to.
    void addTransform(const Node& from, const OCIO::ConstTransformRcPtr& t)
    {
        if (!t)
        {
            return;
        }
        if (auto g = OCIO::DynamicPtrCast<const OCIO::GroupTransform>(t))
        {
            for (int i = 0; i < g->getNumTransforms(); ++i)
            {
                addTransform(from, g->getTransform(i));
            }
        }
        else if (auto c = OCIO::DynamicPtrCast<const OCIO::ColorSpaceTransform>(t))
        {
            add(from, space(c->getSrc()));
            add(from, space(c->getDst()));
        }
        else if (auto l = OCIO::DynamicPtrCast<const OCIO::LookTransform>(t))
        {
            add(from, space(l->getSrc()));
            add(from, space(l->getDst()));
            addLooks(from, l->getLooks());
        }
        else if (auto d = OCIO::DynamicPtrCast<const OCIO::DisplayViewTransform>(t))
        {
            add(from, space(d->getSrc()));
            addView(from, d->getDisplay(), d->getView());
        }
    }

    void build()
    {
        const OCIO::ConstConfigRcPtr& c = m_config;
        for (const OCIO::ConstColorSpaceRcPtr& cs : AllColorSpaces(c))
        {
            const Node n{Node::COLOR_SPACE, cs->getName()};
            m_edges[n];
            addTransform(n, cs->getTransform(OCIO::COLORSPACE_DIR_TO_REFERENCE));
            addTransform(n, cs->getTransform(OCIO::COLORSPACE_DIR_FROM_REFERENCE));
        }
        for (int i = 0; i < c->getNumLooks(); ++i)
        {
            OCIO::ConstLookRcPtr look = c->getLook(c->getLookNameByIndex(i));
            if (!look)
            {
                continue;
            }
            const Node n{Node::LOOK, look->getName()};
            m_edges[n];
            if (look->getProcessSpace() && *look->getProcessSpace())
            {
                add(n, space(look->getProcessSpace()));
            }
            addTransform(n, look->getTransform());
            addTransform(n, look->getInverseTransform());
        }
        for (int i = 0; i < c->getNumNamedTransforms(OCIO::NAMEDTRANSFORM_ALL); ++i)
        {
            const char* name = c->getNamedTransformNameByIndex(OCIO::NAMEDTRANSFORM_ALL, i);
            OCIO::ConstNamedTransformRcPtr nt = c->getNamedTransform(name);
            if (!nt)
            {
                continue;
            }
            const Node n{Node::NAMED_TRANSFORM, nt->getName()};
            m_edges[n];
            addTransform(n, nt->getTransform(OCIO::TRANSFORM_DIR_FORWARD));
            addTransform(n, nt->getTransform(OCIO::TRANSFORM_DIR_INVERSE));
        }
        for (int i = 0; i < c->getNumViewTransforms(); ++i)
        {
            const char* name = c->getViewTransformNameByIndex(i);
            OCIO::ConstViewTransformRcPtr vt = c->getViewTransform(name);
            if (!vt)
            {
                continue;
            }
            const Node n{Node::VIEW_TRANSFORM, vt->getName()};
            m_edges[n];
            addTransform(n, vt->getTransform(OCIO::VIEWTRANSFORM_DIR_TO_REFERENCE));
            addTransform(n, vt->getTransform(OCIO::VIEWTRANSFORM_DIR_FROM_REFERENCE));
        }
        for (int d = 0; d < c->getNumDisplaysAll(); ++d)
        {
            const char* display = c->getDisplayAll(d);
            for (int v = 0; v < c->getNumViews(OCIO::VIEW_DISPLAY_DEFINED, display); ++v)
            {
                const char* view = c->getView(OCIO::VIEW_DISPLAY_DEFINED, display, v);
                addViewEdges(display, view);
            }
            for (int v = 0; v < c->getNumViews(OCIO::VIEW_SHARED, display); ++v)
            {
                const char* view = c->getView(OCIO::VIEW_SHARED, display, v);
                addViewEdges(display, view);
            }
        }
    }

    void addViewEdges(const char* display, const char* view)
    {
        const Node n{Node::VIEW, std::string(display) + "/" + view};
        m_edges[n];
        const char* cs = m_config->getDisplayViewColorSpaceName(display, view);
        if (cs && *cs && std::string(cs) != "<USE_DISPLAY_NAME>")
        {
            add(n, space(cs));
        }
        const char* vt = m_config->getDisplayViewTransformName(display, view);
        if (vt && *vt)
        {
            add(n, {Node::VIEW_TRANSFORM, vt});
        }
        addLooks(n, m_config->getDisplayViewLooks(display, view));
    }

    OCIO::ConstConfigRcPtr m_config;
    std::map<Node, std::vector<Node>> m_edges;
};

}  // namespace

void CheckConfigReferences(const OCIO::ConstConfigRcPtr& config, const std::string& file)
{
    const std::vector<Node> cycle = Graph(config).findCycle();
    if (cycle.empty())
    {
        return;
    }
    std::string chain;
    for (const Node& n : cycle)
    {
        chain += (chain.empty() ? "" : " -> ") + n.describe();
    }
    throw Exception(file +
                    ": the config refers to itself, which OpenColorIO cannot resolve: " + chain);
}

std::vector<OCIO::ConstColorSpaceRcPtr> AllColorSpaces(const OCIO::ConstConfigRcPtr& config)
{
    // One lookup by name per colour space: Config::getColorSpaces() makes
    // two (its set checks each insertion for a duplicate by name).
    std::vector<OCIO::ConstColorSpaceRcPtr> out;
    const int n = config->getNumColorSpaces(OCIO::SEARCH_REFERENCE_SPACE_ALL, OCIO::COLORSPACE_ALL);
    out.reserve(size_t(std::max(n, 0)));
    for (int i = 0; i < n; ++i)
    {
        if (OCIO::ConstColorSpaceRcPtr cs = config->getColorSpace(config->getColorSpaceNameByIndex(
                OCIO::SEARCH_REFERENCE_SPACE_ALL, OCIO::COLORSPACE_ALL, i)))
        {
            out.push_back(cs);
        }
    }
    return out;
}

}  // namespace bandlight
