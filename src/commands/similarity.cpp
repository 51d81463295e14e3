// caskdem similarity N: the model / prototype ratios of the similarity law.

#include <iomanip>
#include <iostream>

#include "commands/commands.h"
#include "commands/validators.h"
#include "model/similarity.h"

namespace caskdem::commands {

void add_similarity(CLI::App& app) {
  auto scale = std::make_shared<double>(3.0);
  CLI::App* cmd = app.add_subcommand("similarity", "Model/prototype ratios of the similarity law for a 1/N model");
  cmd->add_option("scale", *scale, "N (the model is 1/N of the prototype)")->required()->check(positive_number());
  cmd->callback([scale]() {
    std::cout << "similarity law for a 1/" << *scale << " model (acceleration 1, length 1/N, stress 1)\n";
    std::cout << std::left << std::setw(34) << "quantity" << "model / prototype\n";
    for (const SimilarityRow& row : similarity_table()) {
      std::cout << std::left << std::setw(34) << row.quantity << std::setprecision(6)
                << similarity_ratio(*scale, row.dimensions) << "\n";
    }
  });
}

}  // namespace caskdem::commands
