// caskdem similarity N: the model / prototype ratios of the similarity law.

#include <iomanip>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands/commands.h"
#include "commands/validators.h"
#include "core/error.h"
#include "model/similarity.h"

namespace caskdem::commands {

void add_similarity(CLI::App& app) {
  auto scale = std::make_shared<double>(3.0);
  CLI::App* cmd = app.add_subcommand("similarity", "Model/prototype ratios of the similarity law for a 1/N model");
  cmd->add_option("scale", *scale, "N (the model is 1/N of the prototype)")->required()->check(positive_number());
  cmd->callback([scale]() {
    std::vector<double> ratios;
    try {
      for (const SimilarityRow& row : similarity_table()) ratios.push_back(similarity_ratio(*scale, row.dimensions));
    } catch (const std::invalid_argument& e) {
      throw InputError(std::string("scale: ") + e.what());
    }
    std::cout << "similarity law for a 1/" << *scale << " model (acceleration 1, length 1/N, stress 1)\n";
    std::cout << std::left << std::setw(34) << "quantity" << "model / prototype\n";
    for (std::size_t i = 0; i < ratios.size(); ++i) {
      std::cout << std::left << std::setw(34) << similarity_table()[i].quantity << std::setprecision(6) << ratios[i]
                << "\n";
    }
  });
}

}  // namespace caskdem::commands
