#include "creep_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "../cli/contact_inputs.hpp"
#include "../cli/json.hpp"
#include "atomic_file.hpp"
#include "../cli/csv_text.hpp"
#include "number_text.hpp"
#include "results_writer.hpp"
#include "wire.hpp"

namespace cwcampaign {

using cwcli::csv_quote;

TableSpec usetab_axes()
{
    // CONTACT src/usetab_table.f90, itab = 7.
    const int itab = 7;
    TableSpec s;
    for (int i = 1; i <= itab; ++i) s.aob.push_back(double(i) / itab);
    for (double v : {1.2, 1.4, 1.7, 2.0, 2.8, 4.0, 5.6, 8.0, 11.2, 16.0, 22.4, 32.0, 45.0, 65.0,
                     90.0, 130.0, 200.0})
        s.aob.push_back(v);
    std::vector<double> positive;
    for (int i = 0; i <= itab; ++i) positive.push_back(double(i) / itab);
    for (int i = itab - 1; i >= 1; --i) positive.push_back(double(itab) / i);
    positive.push_back(itab / 1e-5); // CONTACT's max(1e-5, i) for i = 0: full sliding
    s.xi = positive;
    s.eta = positive;
    for (auto it = positive.rbegin(); it != positive.rend(); ++it)
        if (*it > 0.0) s.psi.push_back(-*it);
    s.psi.insert(s.psi.end(), positive.begin(), positive.end());
    s.nu = {0.28};
    cw_grid_init(&s.grid);
    return s;
}

uint64_t table_points(const TableSpec& s)
{
    return uint64_t(s.aob.size()) * s.nu.size() * s.xi.size() * s.eta.size() * s.psi.size();
}

uint64_t table_hash(const TableSpec& s)
{
    uint64_t h = fnv1a("creepwork-table-1", 17);
    for (const std::vector<double>* axis : {&s.aob, &s.nu, &s.xi, &s.eta, &s.psi}) {
        const uint64_t n = axis->size();
        h = fnv1a(&n, sizeof n, h);
        h = fnv1a(axis->data(), n * sizeof(double), h);
    }
    const int ints[] = {s.model, s.pressure, s.grid.kind, s.grid.nx, s.grid.ny};
    h = fnv1a(ints, sizeof ints, h);
    return fnv1a(&s.grid.box_scale, sizeof(double), h);
}

std::vector<ContactCase> table_cases(const TableSpec& s)
{
    std::vector<ContactCase> cases;
    cases.reserve(table_points(s));
    for (double aob : s.aob)
        for (double nu : s.nu) {
            double C[4] = {0, 0, 0, 0};
            char message[256] = "";
            const int status = cw_kalker_coefficients(aob, nu, C, message, sizeof message);
            ContactCase base{};
            base.grid = s.grid;
            cw_params_init(&base.params);
            cw_params& p = base.params;
            p.model = s.model;
            p.pressure = s.pressure;
            // The unit contact: c = sqrt(a b) = 1 m, G = 1 Pa, N = 1 N, mu = 1.
            p.a = std::sqrt(aob);
            p.b = 1.0 / std::sqrt(aob);
            p.normal_force = 1.0;
            p.mu = 1.0;
            p.G = 1.0;
            p.nu = nu;
            if (status != CW_OK)
                base.rejected = std::string("a/b = ") + number_text(aob) +
                                  ", nu = " + number_text(nu) + ": " + message;
            for (double xi : s.xi)
                for (double eta : s.eta)
                    for (double psi : s.psi) {
                        ContactCase c = base;
                        if (status == CW_OK) {
                            // Kalker's normalisation inverted, with G c^2 / (mu N) = 1.
                            c.params.xi_x = 3.0 * xi / C[0];
                            c.params.xi_y = 3.0 * eta / C[1];
                            c.params.phi = psi / C[2];
                        }
                        cases.push_back(std::move(c));
                    }
        }
    return cases;
}

namespace {

std::string json_array(const std::vector<double>& v)
{
    std::string s = "[";
    for (double x : v) s += (s.size() > 1 ? ", " : "") + number_text(x);
    return s + "]";
}

const char* model_name(int model)
{
    return model == CW_MODEL_EXACT ? "exact" : model == CW_MODEL_CALIBRATED ? "calibrated"
                                                                            : "fastsim";
}

// DIR/table.json: everything a reader needs to interpolate table.csv.
std::string table_json(const TableSpec& s, const TableSummary& summary)
{
    using cwcli::json_quote;
    std::string j = "{\n";
    const auto member = [&j](const std::string& key, const std::string& rendered, bool last) {
        j += "  " + json_quote(key) + ": " + rendered + (last ? "\n" : ",\n");
    };
    member("format", json_quote("creepwork creep-force table 1"), false);
    member("creepwork", json_quote(cw_version_string()), false);
    member("model", json_quote(model_name(s.model)), false);
    member("grid", json_quote(cwcli::grid_kind_name(s.grid.kind)), false);
    member("nx", std::to_string(s.grid.nx), false);
    member("ny", std::to_string(s.grid.ny), false);
    member("box_scale", number_text(s.grid.box_scale), false);
    member("pressure",
           json_quote(s.pressure == CW_PRESSURE_ELLIPTIC ? "elliptic" : "parabolic"), false);
    member("points", std::to_string(summary.points), false);
    member("failed", std::to_string(summary.failed), false);
    member("order", "[\"aob\", \"nu\", \"xi\", \"eta\", \"psi\"]", false);
    member("index",
           json_quote("k = ipsi + npsi*(ieta + neta*(ixi + nxi*(inu + nnu*iaob))), 0-based: "
                      "line k + 2 of table.csv"),
           false);
    member("axes",
           "{\"aob\": " + json_array(s.aob) + ", \"nu\": " + json_array(s.nu) +
               ", \"xi\": " + json_array(s.xi) + ", \"eta\": " + json_array(s.eta) +
               ", \"psi\": " + json_array(s.psi) + "}",
           false);
    member("normalisation",
           "{\"c\": \"sqrt(a*b)\", \"aob\": \"a/b (a along the rolling direction)\", "
           "\"xi\": \"G*c^2*C11*xi_x/(3*mu*N)\", \"eta\": \"G*c^2*C22*xi_y/(3*mu*N)\", "
           "\"psi\": \"G*c^3*C23*phi/(mu*N)\", \"fx\": \"Fx/(mu*N)\", \"fy\": \"Fy/(mu*N)\", "
           "\"mz\": \"Mz/(mu*N*c)\", \"C11, C22, C23\": \"Kalker 1990 Table E.3 at (a/b, nu), "
           "as cw_kalker_coefficients (CONTACT's interpolation)\"}",
           false);
    member("sign",
           json_quote("Fx, Fy, Mz act on the wheel (creepwork's convention), opposite to the "
                      "creepages: fx = -3 xi, fy = -3 eta in the linear range. CONTACT's USETAB "
                      "tables hold -fx, -fy, -mz at the same xi, eta, psi."),
           false);
    member("symmetries",
           json_quote("F(-xi, -eta, -psi) = -F(xi, eta, psi); (fx, fy, mz)(xi, -eta, -psi) = "
                      "(fx, -fy, -mz)(xi, eta, psi); so (fx, fy, mz)(-xi, eta, psi) = "
                      "(-fx, fy, mz)(xi, eta, psi): xi >= 0, eta >= 0 and psi of both signs "
                      "cover every case"),
           true);
    return j + "}\n";
}

} // namespace

TableSummary write_table(const Journal& journal, const TableSpec& s, const std::string& dir)
{
    TableSummary summary;
    summary.points = table_points(s);
    AtomicFile out(dir + "/table.csv");
    out.write("aob,nu,xi,eta,psi,status,fx,fy,mz,message\n");
    std::string csv;
    const uint64_t npsi = s.psi.size(), neta = s.eta.size(), nxi = s.xi.size(),
                   nnu = s.nu.size();
    for_each_row_in_order(journal, summary.points, [&](uint64_t k, const Outcome& o) {
        const uint64_t ipsi = k % npsi, ieta = (k / npsi) % neta,
                       ixi = (k / (npsi * neta)) % nxi, inu = (k / (npsi * neta * nxi)) % nnu,
                       iaob = k / (npsi * neta * nxi * nnu);
        csv = number_text(s.aob[iaob]) + "," + number_text(s.nu[inu]) + "," +
               number_text(s.xi[ixi]) + "," + number_text(s.eta[ieta]) + "," +
               number_text(s.psi[ipsi]) + "," + status_name(o.status);
        if (o.status == CW_OK) {
            // On the unit contact mu N = 1 and c = 1: fx, fy, mz are Fx, Fy, Mz.
            csv += "," + number_text(o.result.Fx) + "," +
                   number_text(o.result.Fy) + "," +
                   number_text(o.result.Mz) + ",\n";
        } else {
            ++summary.failed;
            if (summary.first_failure.empty()) summary.first_failure = o.message;
            csv += ",,,," + csv_quote(o.message) + "\n";
        }
        out.write(csv);
    });
    out.commit();
    write_file_atomically(dir + "/table.json", table_json(s, summary));
    return summary;
}

} // namespace cwcampaign
