// Transfer functions: evaluation, validation and their JSON form.
#include "vissort/transfer_function.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

namespace vissort {

TransferPoint TransferFunction::at(double s) const {
    if (points.empty())
        return {};
    if (!(s > points.front().scalar))
        return points.front();
    if (s >= points.back().scalar)
        return points.back();
    const auto upper =
        std::upper_bound(points.begin(), points.end(), s,
                         [](double v, const TransferPoint& p) { return v < p.scalar; });
    const TransferPoint& b = *upper;
    const TransferPoint& a = *(upper - 1);
    const double u = (s - a.scalar) / (b.scalar - a.scalar);
    const auto mix = [u](double x, double y) { return x + (y - x) * u; };
    return {s, mix(a.r, b.r), mix(a.g, b.g), mix(a.b, b.b), mix(a.extinction, b.extinction)};
}

Status validateTransferFunction(const TransferFunction& tf) {
    if (tf.points.empty())
        return Status::failure("the transfer function has no points");
    for (std::size_t i = 0; i < tf.points.size(); ++i) {
        const TransferPoint& p = tf.points[i];
        const std::string name = "the transfer function's point " + std::to_string(i);
        for (const double v : {p.scalar, p.r, p.g, p.b, p.extinction})
            if (!std::isfinite(v))
                return Status::failure(name + " has a number that is not finite");
        for (const double c : {p.r, p.g, p.b})
            if (c < 0 || c > 1)
                return Status::failure(name + " has a colour outside [0, 1]");
        if (p.extinction < 0)
            return Status::failure(name + " has a negative extinction");
        if (i > 0 && !(p.scalar > tf.points[i - 1].scalar))
            return Status::failure(
                name + "'s scalar is not above the one before it (scalars must increase)");
    }
    return Status::ok();
}

Result<TransferFunction> parseTransferFunction(const std::string& json_text) {
    using R = Result<TransferFunction>;
    const nlohmann::json doc = nlohmann::json::parse(json_text, nullptr, false);
    if (doc.is_discarded())
        return R::failure("not valid JSON");
    if (!doc.is_object())
        return R::failure("a transfer function is a JSON object with \"points\"");
    TransferFunction tf;
    for (const auto& [key, value] : doc.items()) {
        if (key == "range") {
            if (value == "normalized")
                tf.normalized = true;
            else if (value == "absolute")
                tf.normalized = false;
            else
                return R::failure("\"range\" is \"normalized\" or \"absolute\", not " +
                                  value.dump());
        } else if (key != "points") {
            return R::failure("unknown key \"" + key +
                              "\" (a transfer function has \"range\" and \"points\")");
        }
    }
    if (!doc.contains("points") || !doc["points"].is_array())
        return R::failure("\"points\" must be a list of [scalar, r, g, b, extinction]");
    const nlohmann::json& points = doc["points"];
    for (std::size_t i = 0; i < points.size(); ++i) {
        const nlohmann::json& p = points[i];
        if (!p.is_array() || p.size() != 5 ||
            !std::all_of(p.begin(), p.end(), [](const nlohmann::json& v) { return v.is_number(); }))
            return R::failure("\"points\"[" + std::to_string(i) +
                              "] must be [scalar, r, g, b, extinction], 5 numbers");
        tf.points.push_back({p[0].get<double>(), p[1].get<double>(), p[2].get<double>(),
                             p[3].get<double>(), p[4].get<double>()});
    }
    if (Status valid = validateTransferFunction(tf); !valid)
        return R::failure(valid.error);
    return R{std::move(tf), {}};
}

std::string transferFunctionJson(const TransferFunction& tf) {
    nlohmann::json points = nlohmann::json::array();
    for (const TransferPoint& p : tf.points)
        points.push_back({p.scalar, p.r, p.g, p.b, p.extinction});
    return nlohmann::json{{"range", tf.normalized ? "normalized" : "absolute"}, {"points", points}}
        .dump();
}

} // namespace vissort
