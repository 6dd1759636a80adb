// See contact_network.h.
#include "grainlab/contact_network.h"

namespace grainlab {

ContactColumns contactColumns(const ContactNetwork& network) {
    const std::size_t n = network.contacts.size();
    ContactColumns c;
    for (auto* v : {&c.first, &c.second, &c.shift1, &c.shift2}) {
        v->resize(n);
    }
    for (auto* v : {&c.normal1, &c.normal2, &c.point1, &c.point2, &c.branch1, &c.branch2,
                    &c.overlap, &c.normalForce, &c.tangentialForce}) {
        v->resize(n);
    }
    c.sliding.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        const ContactRecord& r = network.contacts[k];
        c.first[k] = r.first;
        c.second[k] = r.second;
        c.shift1[k] = r.shift1;
        c.shift2[k] = r.shift2;
        c.normal1[k] = r.normal1;
        c.normal2[k] = r.normal2;
        c.point1[k] = network.x1[r.first] + r.point1;
        c.point2[k] = network.x2[r.first] + r.point2;
        c.branch1[k] = r.branch1;
        c.branch2[k] = r.branch2;
        c.overlap[k] = r.overlap;
        c.normalForce[k] = r.normalForce;
        c.tangentialForce[k] = r.tangentialForce;
        c.sliding[k] = r.sliding ? 1 : 0;
    }
    return c;
}

} // namespace grainlab
